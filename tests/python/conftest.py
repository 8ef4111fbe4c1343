# SPDX-License-Identifier: GPL-3.0-or-later
"""Fixtures of the Python package's tests: the package from the build tree
(PYTHONPATH=BUILD/python, set by scripts/run-tests.sh), the cable program,
scratch directories with the constants files the tests need."""
import os
import shutil
import subprocess
import sys

import pytest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), '..', '..'))
BUILD = os.path.join(ROOT, os.environ.get('CABLE_BUILD', 'build/release'))
PYTHON = '/usr/bin/python3'


@pytest.fixture
def work(tmp_path, monkeypatch):
    """A scratch directory, the current directory while the test runs."""
    monkeypatch.chdir(tmp_path)
    return tmp_path


def copy_in(work, *paths):
    for p in paths:
        shutil.copy(os.path.join(ROOT, p), work)


def run_script(work, text, name='t.auto', timeout=1200):
    """Runs the script text as `cable replay` does (a new process); returns
    (status, stdout, stderr)."""
    path = os.path.join(str(work), name)
    with open(path, 'w') as f:
        f.write(text)
    env = dict(os.environ, PYTHONPATH=os.path.join(BUILD, 'python'))
    p = subprocess.run([os.path.join(BUILD, 'cable'), 'replay', name], capture_output=True, text=True,
                       timeout=timeout, env=env, cwd=str(work))
    return p.returncode, p.stdout, p.stderr


def snapshot(d):
    """{name: bytes} of every file in d."""
    out = {}
    for n in sorted(os.listdir(d)):
        p = os.path.join(d, n)
        if os.path.isfile(p):
            with open(p, 'rb') as f:
                out[n] = f.read()
    return out
