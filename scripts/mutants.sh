#!/usr/bin/env bash
# The mutation check of include/ (docs/quality.md, "Mutation score"): every mutant of
# tests/mutants.txt applied on its own to a copy of include/, the doctest files built with g++ -O0
# in build/mutants/ and run until one kills it. Outside CI: about 40 minutes on two cores.
#   bash scripts/mutants.sh                  every mutant; the score and the survivors
#   bash scripts/mutants.sh --check          only the stale check (each snippet occurs once)
#   bash scripts/mutants.sh --survivors      the survivors of the last run again
#   bash scripts/mutants.sh --only 3,17      these mutants
# JOBS=N mutants at a time (default 2); CXX the compiler (default g++). Niced.
set -euo pipefail
cd "$(dirname "$0")/.."
exec nice -n 10 python3 scripts/mutants.py "$@"
