# SPDX-License-Identifier: GPL-3.0-or-later
"""SPDX lines (issue 27): every source file of the repository carries one
(scripts/spdx.py --check), and --apply puts it on top, after a shebang."""
import os
import stat
import subprocess

from conftest import PYTHON, ROOT

SPDX = os.path.join(ROOT, 'scripts', 'spdx.py')


def _run(*args):
    return subprocess.run([PYTHON, SPDX] + list(args), capture_output=True, text=True)


def test_every_source_has_the_line():
    p = _run('--check')
    assert p.returncode == 0, p.stdout + p.stderr
    assert ' 0 of ' in p.stderr
    n = int(p.stderr.split(' of ')[1].split()[0])
    assert n > 250   # the C, Python, shell sources and the Makefile


def test_license_file():
    with open(os.path.join(ROOT, 'LICENSE')) as f:
        assert 'GNU GENERAL PUBLIC LICENSE' in f.read(200)


def test_apply_and_check(tmp_path):
    files = {
        'a.sh': '#!/usr/bin/env bash\necho a\n',
        'b.py': '"""doc"""\nx = 1\n',
        'c.c': '/* c */\nint c;\n',
        'd.h': '#ifndef D\n#define D\n#endif\n',
        'Makefile': 'all:\n\ttrue\n',
        'tool': '#!/bin/sh\ntrue\n',
        'notes.txt': 'prose\n',
        'tests/data/x.c': 'data whose line numbers a test checks\n',
        'e.py': '#!/usr/bin/python3\n# SPDX-License-Identifier: MIT\nx = 2\n',
    }
    for name, text in files.items():
        p = tmp_path / name
        p.parent.mkdir(parents=True, exist_ok=True)
        p.write_text(text)
    (tmp_path / 'a.sh').chmod(0o755)
    p = _run('--check', '--root', str(tmp_path))
    assert p.returncode == 1
    assert p.stdout.split() == ['Makefile', 'a.sh', 'b.py', 'c.c', 'd.h', 'tool']
    p = _run('--apply', '--root', str(tmp_path))
    assert p.returncode == 0, p.stderr
    line = 'SPDX-License-Identifier: GPL-3.0-or-later'
    assert (tmp_path / 'a.sh').read_text() == '#!/usr/bin/env bash\n# %s\necho a\n' % line
    assert (tmp_path / 'tool').read_text() == '#!/bin/sh\n# %s\ntrue\n' % line
    assert (tmp_path / 'b.py').read_text() == '# %s\n"""doc"""\nx = 1\n' % line
    assert (tmp_path / 'c.c').read_text() == '/* %s */\n/* c */\nint c;\n' % line
    assert (tmp_path / 'Makefile').read_text().startswith('# %s\nall:' % line)
    assert (tmp_path / 'notes.txt').read_text() == 'prose\n'
    assert (tmp_path / 'tests/data/x.c').read_text() == files['tests/data/x.c']
    assert (tmp_path / 'e.py').read_text() == files['e.py']   # has a line: left alone
    assert stat.S_IMODE((tmp_path / 'a.sh').stat().st_mode) == 0o755
    assert _run('--check', '--root', str(tmp_path)).returncode == 0
    before = {n: (tmp_path / n).read_text() for n in files}
    _run('--apply', '--root', str(tmp_path))
    assert before == {n: (tmp_path / n).read_text() for n in files}
