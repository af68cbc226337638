"""Shared helpers of the Python module's tests (run by ctest: python_pytest)."""

import os
import pathlib

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]


def parse_candump(line):
    """(id, data, extended) of a candump line "(t) can0 195#040000002A" or "195#04..."."""
    text = line.split()[-1]
    ident, _, data = text.partition("#")
    return int(ident, 16), bytes.fromhex(data), len(ident) > 3


@pytest.fixture
def repo():
    return REPO


def env_program(name):
    path = os.environ.get(name)
    if not path or not os.path.exists(path):
        pytest.skip(f"{name} not set (run through ctest)")
    return path
