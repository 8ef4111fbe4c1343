# SPDX-License-Identifier: GPL-3.0-or-later
"""The README's pictures (doc/img) are what `make doc-img` (scripts/doc-img.sh)
makes: the knot72 scene replayed in a scratch copy gives the same diagram and
renders, pixel for pixel up to anti-aliasing.

Tolerance: the pictures are drawn from the scene's numbers, which agree
between runs to the solver's tolerances (1e-7 relative and below, far under a
pixel), so a fresh picture differs only where a line or tube edge falls
within a rounding of a pixel boundary.  A pixel counts as changed when a
channel moves by more than 8/255; at most 0.2 % of the pixels may change (a
few hundred of 307,200), where a changed mark, label, line or tube moves
thousands.  The caption (tEXt chunk) must be the same text."""
import os
import shutil
import subprocess

import numpy as np
import pytest

from conftest import BUILD, ROOT

PICTURES = ('knot72.png', 'knot72_b.png', 'knot72_d.png', 'knot72_mirror.png')
CHANGED = 8 / 255
MAX_CHANGED = 0.002


def png_caption(path):
    """The tEXt 'Description' of a PNG (None: none), read chunk by chunk."""
    import struct
    data = open(path, 'rb').read()
    k = 8
    while k + 8 <= len(data):
        n, kind = struct.unpack('>I4s', data[k:k + 8])
        if kind == b'tEXt':
            key, _, text = data[k + 8:k + 8 + n].partition(b'\0')
            if key == b'Description':
                return text.decode('latin-1')
        k += 12 + n
    return None


@pytest.mark.skipif(bool(os.environ.get('CABLE_TEST_QUICK')), reason='CABLE_TEST_QUICK')
def test_readme_pictures_are_the_scenes(tmp_path):
    import matplotlib.image as mpimg
    d = tmp_path / 'knot72'
    d.mkdir()
    for f in ('c.knot72', 'c.knot72sym', 'knot72.auto'):
        shutil.copy(os.path.join(ROOT, 'runs', 'knot72', f), str(d))
    env = dict(os.environ, PYTHONPATH=os.path.join(BUILD, 'python'))
    p = subprocess.run([os.path.join(BUILD, 'cable'), 'replay', str(d / 'knot72.auto')], capture_output=True,
                       text=True, env=env, timeout=1800)
    assert p.returncode == 0, p.stderr
    for name in PICTURES:
        fresh, readme = str(d / name), os.path.join(ROOT, 'doc', 'img', name)
        a, b = mpimg.imread(fresh)[:, :, :3], mpimg.imread(readme)[:, :, :3]
        assert a.shape == b.shape, name
        changed = (np.abs(a - b).max(axis=2) > CHANGED).mean()
        assert changed <= MAX_CHANGED, '%s: %.3f %% of the pixels differ from doc/img (make doc-img)' % (
            name, 100 * changed)
        assert png_caption(readme) is not None and png_caption(fresh) == png_caption(readme), name
