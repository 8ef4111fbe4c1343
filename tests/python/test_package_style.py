# SPDX-License-Identifier: GPL-3.0-or-later
"""The Python package's conventions (issue 27): every public module of
python/cable declares __all__ (PEP 8: after the docstring), whose names
exist and include each public function and class the module defines; and
no line is longer than MAX_LINE.

Line length: PEP 8 allows teams to raise the limit from 79 to 99 columns;
cable takes 99 for code, comments and docstrings alike (its modules embed
the view page's CSS and JavaScript, and its messages name files, lines and
keys), so this test, not a configuration file, is where the choice lives."""
import ast
import glob
import importlib
import os

from conftest import ROOT

MAX_LINE = 99
MODULES = sorted(glob.glob(os.path.join(ROOT, 'python', 'cable', '*.py')))


def _defined(path):
    with open(path, encoding='utf-8') as f:
        tree = ast.parse(f.read())
    return [n.name for n in tree.body
            if isinstance(n, (ast.FunctionDef, ast.ClassDef)) and not n.name.startswith('_')]


def test_every_public_module_has_all():
    assert len(MODULES) > 15
    for path in MODULES:
        name = os.path.basename(path)[:-3]
        if name == '__main__':
            continue   # the entry point of python3 -m cable, not imported
        mod = importlib.import_module('cable' if name == '__init__' else 'cable.' + name)
        assert hasattr(mod, '__all__'), name
        missing = [n for n in mod.__all__ if not hasattr(mod, n)]
        assert not missing, (name, missing)
        unlisted = [n for n in _defined(path) if n not in mod.__all__]
        assert not unlisted, (name, unlisted)


def test_star_import_gives_the_commands():
    ns = {}
    exec('from cable import *', ns)
    for n in ('run', 'loadbd', 'save', 'Result', 'CableError', 'CableKeyError'):
        assert n in ns, n
    assert '_delegate' not in ns and 'threading' not in ns


def test_line_lengths():
    long = []
    for path in MODULES:
        with open(path, encoding='utf-8') as f:
            for k, line in enumerate(f, 1):
                if len(line.rstrip('\n')) > MAX_LINE:
                    long.append('%s:%d: %d columns' % (os.path.basename(path), k,
                                                       len(line.rstrip('\n'))))
    assert not long, '\n'.join(long)
