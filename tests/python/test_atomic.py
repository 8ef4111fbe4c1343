# SPDX-License-Identifier: GPL-3.0-or-later
"""cable.atomic, the package's one atomic writer: whole files or none, mode
0644 like the C writer's, no temporary file left behind; and no other
module writes its own temporary-and-rename."""
import glob
import os
import stat

import pytest

from cable import atomic
from conftest import ROOT


def test_write_text_whole_file_and_mode(work):
    p = os.path.join(str(work), 'a.txt')
    assert atomic.write_text(p, 'one\n') == p
    atomic.write_text(p, 'two\n')
    with open(p) as f:
        assert f.read() == 'two\n'
    assert stat.S_IMODE(os.stat(p).st_mode) == 0o644
    assert os.listdir(str(work)) == ['a.txt']


def test_failure_leaves_the_old_file(work):
    p = os.path.join(str(work), 'b.txt')
    atomic.write_text(p, 'old\n')
    with pytest.raises(RuntimeError):
        with atomic.replacing(p) as tmp:
            with open(tmp, 'w') as f:
                f.write('half')
            raise RuntimeError('stopped half-way')
    with open(p) as f:
        assert f.read() == 'old\n'
    assert os.listdir(str(work)) == ['b.txt']


def test_copy_file(work):
    src = os.path.join(str(work), 's')
    with open(src, 'wb') as f:
        f.write(b'\x00\x01data')
    atomic.copy_file(src, os.path.join(str(work), 'd'))
    with open(os.path.join(str(work), 'd'), 'rb') as f:
        assert f.read() == b'\x00\x01data'


def test_no_other_temporary_and_rename():
    """The package and the scripts write through cable.atomic only."""
    files = glob.glob(os.path.join(ROOT, 'python', 'cable', '*.py'))
    files += glob.glob(os.path.join(ROOT, 'scripts', '*.py'))
    own = [f for f in files if os.path.basename(f) != 'atomic.py']
    assert len(own) > 10
    for f in own:
        with open(f) as fh:
            text = fh.read()
        assert 'mkstemp(' not in text, f
        assert "+ '.tmp'" not in text, f
