# SPDX-License-Identifier: GPL-3.0-or-later
"""scripts/link_readings_table.py reads its s-files with cable's own loadbd
(no second reader): the labelled points and their parameters as cable
reads them, also from AUTO-07p's s-files (three-digit exponents)."""
import importlib.util
import os
import shutil

from conftest import ROOT


def _table():
    spec = importlib.util.spec_from_file_location(
        'link_readings_table', os.path.join(ROOT, 'scripts', 'link_readings_table.py'))
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_labelled_points_from_loadbd(work):
    t = _table()
    shutil.copy(os.path.join(ROOT, 'tests', 'data', 's.link62_buckled'), 's.mode')
    pts = t.labelled(os.path.join(str(work), 's.mode'), ('EP',))
    assert [p['lab'] for p in pts] == [41]
    # PAR(1) = T as the s-file's text has it
    assert pts[0]['par'][t.T] == -7.1079605096
    assert t.labelled(os.path.join(str(work), 's.mode')) == []   # no UZ point
    assert t.labelled(os.path.join(str(work), 's.none')) == []
    assert os.getcwd() == str(work)


def test_reads_auto07p_files(work):
    t = _table()
    shutil.copy(os.path.join(ROOT, 'tests', 'data', 's.auto07p'), 's.a')
    pts = t.labelled(os.path.join(str(work), 's.a'), ('BP',))
    assert [p['lab'] for p in pts] == [2] and pts[0]['par'][0] == 1.5
    assert not os.path.exists(os.path.join(ROOT, 'scripts', 'sfile.py'))
