#!/usr/bin/env python3
"""The mutation check of include/ (docs/quality.md, "Mutation score").

Applies each mutant of tests/mutants.txt to a copy of include/, one at a time, and runs the
doctest files against it until one of them kills it: a file that no longer compiles (a
static_assert fails) or whose run fails. The files tried first are the test file named after the
mutated header, then the files that killed most mutants so far; only the files that include the
mutated header are tried. A mutant none of them kills survives. Prints the score and the
survivors; writes build/mutants/results.txt.

  python3 scripts/mutants.py                 # every mutant
  python3 scripts/mutants.py --check         # only: every snippet occurs once (stale ones listed)
  python3 scripts/mutants.py --only 3,17     # these mutants (numbers as printed)
  python3 scripts/mutants.py --survivors     # the survivors of the last run again
  JOBS=2 CXX=g++ python3 scripts/mutants.py

The mutant list (tests/mutants.txt): blocks separated by a blank line, each
    file: include/powerkey/....hpp
    find: one line of the file's text, which must occur exactly once in the file
    replace: what it becomes
    equivalent: why no test can tell (optional: the mutant is counted apart)
    tests: the test files (names without .cpp) to try first (optional)
and '#' lines as comments. A snippet that no longer occurs exactly once is reported as stale
(and fails the run), never skipped silently.
"""

import argparse
import concurrent.futures
import json
import os
import pathlib
import shutil
import subprocess
import sys
import threading
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
TESTS = ROOT / "tests"
OUT = ROOT / "build" / "mutants"
CXX = os.environ.get("CXX", "g++")
FLAGS = ["-std=c++20", "-O0", "-w"]
# The tool's pieces need the tool's libraries: they are not part of this check.
SKIP = {"test_tool_parts.cpp", "test_dbc.cpp"}
RUN_TIMEOUT = 120


class Mutant:
    def __init__(self, number, line, fields):
        self.number = number
        self.line = line
        self.file = fields.get("file", "")
        self.find = fields.get("find", "")
        self.replace = fields.get("replace", "")
        self.equivalent = fields.get("equivalent")
        self.tests = fields.get("tests", "").split()
        self.stale = None

    def label(self):
        return f"#{self.number} {self.file}: {self.find.strip()!r} -> {self.replace.strip()!r}"


def parse(path):
    mutants, fields, start, fields_of = [], {}, 0, {}
    lines = path.read_text().splitlines() + [""]
    for n, raw in enumerate(lines, 1):
        if raw.startswith("#"):
            continue
        if not raw.strip():
            if fields:
                mutants.append(Mutant(len(mutants) + 1, start, fields))
                fields_of[len(mutants)] = fields
                fields = {}
            continue
        key, sep, value = raw.partition(": ")
        if not sep or key not in ("file", "find", "replace", "equivalent", "tests"):
            sys.exit(f"{path}:{n}: expected 'file: ', 'find: ', 'replace: ', 'equivalent: ' or 'tests: '")
        if not fields:
            start = n
        fields[key] = value
    for m in mutants:
        if not m.file or not m.find or "replace" not in fields_of[m.number]:
            sys.exit(f"{path}:{m.line}: a mutant needs file, find and replace")
        if m.find == m.replace:
            sys.exit(f"{path}:{m.line}: the replacement is the snippet itself")
    return mutants


def check_stale(mutants):
    for m in mutants:
        p = ROOT / m.file
        if not p.is_file():
            m.stale = "no such file"
            continue
        count = p.read_text().count(m.find)
        if count != 1:
            m.stale = f"the snippet occurs {count} times"
    return [m for m in mutants if m.stale]


def test_sources():
    files = sorted(p for p in TESTS.glob("test_*.cpp") if p.name not in SKIP)
    return files + [TESTS / "extra_model.cpp"]


def defines():
    return [f'-DPOWERKEY_SHARED_DIR="{ROOT.parent / "shared"}"',
            f'-DPOWERKEY_SOURCE_DIR="{ROOT}"']


class Worker:
    """A copy of include/ in which one mutant at a time is applied."""

    def __init__(self, n):
        self.dir = OUT / f"worker{n}"
        if self.dir.exists():
            shutil.rmtree(self.dir)
        shutil.copytree(ROOT / "include", self.dir / "include")

    def compile_and_run(self, src, main_o):
        obj = self.dir / (src.stem + ".o")
        exe = self.dir / src.stem
        for p in (obj, exe):
            p.unlink(missing_ok=True)
        c = subprocess.run([CXX, *FLAGS, f"-I{self.dir / 'include'}", f"-I{TESTS}", *defines(),
                            "-c", str(src), "-o", str(obj)], capture_output=True)
        if c.returncode != 0:
            return "compile"
        link = subprocess.run([CXX, str(main_o), str(obj), "-o", str(exe)], capture_output=True)
        if link.returncode != 0:
            return "link"
        try:
            r = subprocess.run([str(exe), "--no-colors", "--minimal"], capture_output=True,
                               cwd=ROOT, timeout=RUN_TIMEOUT)
        except subprocess.TimeoutExpired:
            return "timeout"
        return None if r.returncode == 0 else "run"


def depends(src):
    """The headers under include/ that src includes (g++ -MM)."""
    r = subprocess.run([CXX, *FLAGS, f"-I{ROOT / 'include'}", f"-I{TESTS}", *defines(), "-MM",
                        str(src)], capture_output=True, text=True, check=True)
    words = r.stdout.replace("\\\n", " ").split()
    inc, tests = str(ROOT / "include") + "/", str(TESTS) + "/"
    return ({w[len(inc):] for w in words if w.startswith(inc)},
            {w[len(tests):] for w in words if w.startswith(tests) and w.endswith(".hpp")})


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--list", default=str(TESTS / "mutants.txt"))
    ap.add_argument("--check", action="store_true", help="only report stale snippets")
    ap.add_argument("--only", help="mutant numbers: 3,17,20-40")
    ap.add_argument("--survivors", action="store_true", help="the last run's survivors")
    ap.add_argument("--max-files", type=int, default=0,
                    help="try only this many files per mutant, the likeliest (0: every file); "
                         "a mutant none of them kills is reported as alive after them")
    ap.add_argument("--no-baseline", action="store_true",
                    help="skip the run of every file without a mutant (it must pass)")
    args = ap.parse_args()

    mutants = parse(pathlib.Path(args.list))
    stale = check_stale(mutants)
    per_file = {}
    for m in mutants:
        per_file[m.file] = per_file.get(m.file, 0) + 1
    print(f"{len(mutants)} mutants over {len(per_file)} headers, "
          f"{sum(1 for m in mutants if m.equivalent)} marked equivalent")
    for m in stale:
        print(f"STALE {m.label()}: {m.stale}")
    if args.check:
        return 1 if stale else 0
    if stale:
        print("fix the stale snippets first (tests/mutants.txt)")
        return 1

    chosen = [m for m in mutants if not m.equivalent]
    if args.only:
        wanted = set()
        for part in args.only.split(","):
            first, _, last = part.partition("-")
            wanted.update(range(int(first), int(last or first) + 1))
        chosen = [m for m in mutants if m.number in wanted]
    elif args.survivors:
        last = OUT / "survivors.txt"
        wanted = {int(x) for x in last.read_text().split()} if last.exists() else set()
        chosen = [m for m in mutants if m.number in wanted]

    OUT.mkdir(parents=True, exist_ok=True)
    jobs = int(os.environ.get("JOBS", "2"))
    main_o = OUT / "main.o"
    if not main_o.exists():
        subprocess.run([CXX, *FLAGS, "-c", str(TESTS / "main.cpp"), "-o", str(main_o)],
                       check=True)
    sources = test_sources()
    deps, local = {}, {}
    for s in sources:
        deps[s], local[s] = depends(s)

    # What a file costs to build and run: measured (build/mutants/seconds.json, kept from run to
    # run), else guessed from the size of its source and the test headers it includes.
    saved = OUT / "seconds.json"
    seconds = {TESTS / k: v for k, v in json.loads(saved.read_text()).items()} \
        if saved.exists() else {}
    guess = {s: (s.stat().st_size + sum((TESTS / h).stat().st_size for h in local[s])) / 4000.0
             for s in sources}

    def cost(s):
        return max(seconds.get(s, guess[s]), 1.0)

    workers = [Worker(i) for i in range(jobs)]
    free = list(workers)
    lock = threading.Lock()

    def take():
        with lock:
            return free.pop()

    def give(w):
        with lock:
            free.append(w)

    if not args.no_baseline:
        print(f"baseline: {len(sources)} files without a mutant")

        def base(src):
            w = take()
            try:
                t = time.monotonic()
                fault = w.compile_and_run(src, main_o)
                seconds[src] = time.monotonic() - t
                return src, fault
            finally:
                give(w)

        with concurrent.futures.ThreadPoolExecutor(jobs) as ex:
            failed = [(s, f) for s, f in ex.map(base, sources) if f]
        for s, f in failed:
            print(f"baseline FAILS: {s.name} ({f})")
        if failed:
            return 1

    # Which file killed mutants of which header, kept from run to run (build/mutants/kills.json).
    kills_file = OUT / "kills.json"
    kills = {}
    if kills_file.exists():
        for key, n in json.loads(kills_file.read_text()).items():
            header, _, name = key.partition(" ")
            kills[(header, TESTS / name)] = n

    def order(m):
        header = pathlib.Path(m.file)
        rel = str(header.relative_to("include"))
        stem = header.stem if header.parent.name == "powerkey" else \
            f"{header.parent.name}_{header.stem}"
        own = {s for s in sources if s.stem == f"test_{stem}" or
               s.stem.startswith(f"test_{stem}_")}
        # Cheap and likely first: the kills so far (and the header's own test file) per second of
        # building the file.
        with lock:
            def score(s):
                here = kills.get((m.file, s), 0)
                anywhere = sum(n for (h, f), n in kills.items() if f == s)
                return (5 * here + 0.05 * anywhere + (8 if s in own else 0) + 1) / cost(s)
            ranked = sorted((s for s in sources if rel in deps[s]), key=score, reverse=True)
        hinted = [s for name in m.tests for s in ranked if s.stem == name]
        return hinted + [s for s in ranked if s not in hinted]

    def run(m):
        w = take()
        target = w.dir / pathlib.Path(m.file)
        original = target.read_text()
        try:
            target.write_text(original.replace(m.find, m.replace, 1))
            t = time.monotonic()
            candidates = order(m)
            if args.max_files:
                candidates = candidates[:args.max_files]
            for src in candidates:
                start = time.monotonic()
                fault = w.compile_and_run(src, main_o)
                with lock:
                    if fault != "compile":  # a file that fails early says little of its cost
                        seconds[src] = time.monotonic() - start
                if fault:
                    with lock:
                        kills[(m.file, src)] = kills.get((m.file, src), 0) + 1
                    return m, f"killed by {src.name} ({fault})", time.monotonic() - t
            return m, None, time.monotonic() - t
        finally:
            target.write_text(original)
            give(w)

    saved.write_text(json.dumps({s.name: v for s, v in seconds.items()}))
    print(f"{len(chosen)} mutants, {jobs} at a time")
    survivors, lines = [], []
    with concurrent.futures.ThreadPoolExecutor(jobs) as ex:
        for m, verdict, spent in ex.map(run, chosen):
            alive = "ALIVE   (marked equivalent)" if m.equivalent else "ALIVE  "
            line = f"{'KILLED ' if verdict else alive} {m.label()}  " \
                   f"[{verdict or 'no test failed'}, {spent:.0f} s]"
            print(line, flush=True)
            lines.append(line)
            with lock:  # kept as it goes: an interrupted run still teaches the next one
                saved.write_text(json.dumps({s.name: v for s, v in seconds.items()}))
                kills_file.write_text(
                    json.dumps({f"{h} {s.name}": n for (h, s), n in kills.items()}))
            if not verdict:
                survivors.append(m)

    # An equivalent mutant chosen by --only or --survivors is run as a check of its reason: it is
    # counted apart, and one that a test kills is reported (its reason is wrong).
    equivalent = [m for m in mutants if m.equivalent]
    scored = [m for m in chosen if not m.equivalent]
    survivors_run = [m for m in survivors if not m.equivalent]
    killed = len(scored) - len(survivors_run)
    score = 100.0 * killed / len(scored) if scored else 100.0
    summary = (f"score: {killed} of {len(scored)} non-equivalent mutants killed ({score:.1f} %); "
               f"{len(equivalent)} equivalent")
    print(summary)
    for m in survivors_run:
        print(f"SURVIVOR {m.label()}")
    wrong = [m for m in chosen if m.equivalent and m not in survivors]
    for m in wrong:
        print(f"KILLED BUT MARKED EQUIVALENT {m.label()}: {m.equivalent}")
    if not args.only and not args.survivors:
        for m in equivalent:
            print(f"EQUIVALENT {m.label()}: {m.equivalent}")
    survivors = survivors_run
    saved.write_text(json.dumps({s.name: v for s, v in seconds.items()}))
    kills_file.write_text(json.dumps({f"{h} {s.name}": n for (h, s), n in kills.items()}))
    (OUT / "results.txt").write_text("\n".join(lines + [summary]) + "\n")
    (OUT / "survivors.txt").write_text(" ".join(str(m.number) for m in survivors) + "\n")
    return 0 if not survivors and not wrong else 2


if __name__ == "__main__":
    sys.exit(main())
