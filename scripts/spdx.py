#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""SPDX license lines of cable's sources (LICENSE: GPL-3.0-or-later).

Usage: /usr/bin/python3 scripts/spdx.py --check | --apply [--root DIR]
  --check  list the source files without an SPDX-License-Identifier line in
           their first lines; exit 1 when there is one
  --apply  add the line at the top of each such file, after a shebang line
           (#!...) where there is one; files that have it are left alone

Sources: C and header files (.c, .h), Python (.py), shell (.sh, and files
whose shebang names sh or bash) and makefiles (Makefile, *.mk), the files
git tracks under DIR (every file below it outside a checkout).  Test data
(tests/data, tests/fuzz: inputs whose bytes and line numbers the tests
check) are not sources.
"""
import os
import subprocess
import sys

# cable's one atomic writer (python/cable/atomic.py), loaded as a file
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'python', 'cable'))
sys.dont_write_bytecode = True
from atomic import write_text  # noqa: E402

LICENSE_ID = 'GPL-3.0-or-later'
TAG = 'SPDX-License-Identifier:'
C_LINE = '/* %s %s */\n' % (TAG, LICENSE_ID)
HASH_LINE = '# %s %s\n' % (TAG, LICENSE_ID)
# the tag counts when it stands in one of the first lines (after a shebang,
# an encoding line or a file's title comment)
HEAD_LINES = 5
SKIP_DIRS = ('tests/data/', 'tests/fuzz/', 'build/')


def _files(root):
    try:
        out = subprocess.run(['git', 'ls-files', '-z'], cwd=root, capture_output=True,
                             check=True).stdout
        names = [n for n in out.decode('utf-8').split('\0') if n]
    except (OSError, subprocess.CalledProcessError):
        names = []
        for d, subdirs, files in os.walk(root):
            subdirs[:] = [s for s in subdirs if not s.startswith('.') or s == '.ci']
            names += [os.path.relpath(os.path.join(d, f), root) for f in files]
    return sorted(n.replace(os.sep, '/') for n in names)


def comment_style(root, name):
    """'c', 'hash' or None (not a source)."""
    if name.startswith(SKIP_DIRS):
        return None
    base = os.path.basename(name)
    if base.endswith(('.c', '.h')):
        return 'c'
    if base.endswith(('.py', '.sh', '.mk')) or base == 'Makefile':
        return 'hash'
    path = os.path.join(root, name)
    if '.' in base or not os.path.isfile(path) or os.path.islink(path):
        return None
    try:
        with open(path, 'rb') as f:
            first = f.readline(200)
    except OSError:
        return None
    if first.startswith(b'#!') and (b'sh' in first.split(b'/')[-1] or b'python' in first):
        return 'hash'
    return None


def has_tag(text):
    return any(TAG in line for line in text.split('\n')[:HEAD_LINES])


def with_tag(text, style):
    """text with the SPDX line on top (after a shebang line)."""
    line = C_LINE if style == 'c' else HASH_LINE
    if text.startswith('#!'):
        nl = text.find('\n')
        if nl < 0:
            return text + '\n' + line
        return text[:nl + 1] + line + text[nl + 1:]
    return line + text


def sources(root):
    for name in _files(root):
        style = comment_style(root, name)
        if style:
            yield name, style


def main(argv):
    args = list(argv)
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    if '--root' in args:
        i = args.index('--root')
        if i + 1 >= len(args):
            sys.exit('spdx.py: --root needs a directory')
        root = args[i + 1]
        del args[i:i + 2]
    if args not in (['--check'], ['--apply']):
        sys.exit(__doc__.split('\n\n')[1])
    missing = []
    count = 0
    for name, style in sources(root):
        path = os.path.join(root, name)
        with open(path, encoding='utf-8', newline='') as f:
            text = f.read()
        count += 1
        if has_tag(text):
            continue
        missing.append(name)
        if args == ['--apply']:
            write_text(path, with_tag(text, style), mode=os.stat(path).st_mode & 0o7777)
    if args == ['--check']:
        for name in missing:
            print(name)
        print('spdx: %d of %d source files without an SPDX line' % (len(missing), count),
              file=sys.stderr)
        return 1 if missing else 0
    print('spdx: added the SPDX line to %d of %d source files' % (len(missing), count))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
