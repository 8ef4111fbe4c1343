# SPDX-License-Identifier: GPL-3.0-or-later
"""doc/constants.md's key table is the one table of constants keys
(include/cable/cable_constants_keys.h) as scripts/gen_constants_doc.py writes
it: it cannot drift from the keys the parser, the defaults and the Python
layout use."""
import os
import re
import shutil
import subprocess
import sys

from cable._cable import constants_layout

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
GEN = os.path.join(ROOT, 'scripts', 'gen_constants_doc.py')
DOC = os.path.join(ROOT, 'doc', 'constants.md')
sys.path.insert(0, os.path.join(ROOT, 'scripts'))
import gen_constants_doc  # noqa: E402


def check(doc):
    return subprocess.run([sys.executable, GEN, '--check', '--doc', doc], capture_output=True, text=True)


def test_doc_table_is_the_generated_one():
    r = check(DOC)
    assert r.returncode == 0, r.stdout + r.stderr


def test_a_changed_row_is_found(tmp_path):
    doc = str(tmp_path / 'constants.md')
    shutil.copy(DOC, doc)
    with open(doc, encoding='utf-8') as f:
        text = f.read()
    changed = text.replace('| `NTST` | integer | 20 | >= 1 |', '| `NTST` | integer | 30 | >= 1 |', 1)
    assert changed != text
    with open(doc, 'w', encoding='utf-8') as f:
        f.write(changed)
    r = check(doc)
    assert r.returncode == 1 and 'differs' in r.stdout
    subprocess.run([sys.executable, GEN, '--doc', doc], check=True)
    assert check(doc).returncode == 0


def test_script_reads_the_table_the_library_was_built_from():
    """The rows the script reads from the header are the compiled table's:
    the keys of every printed line, in order (a row the script's pattern
    missed, or a line column it misread, fails here)."""
    rows = gen_constants_doc.rows()
    lines = {}
    for r in rows:
        if r['line'] != '0':
            lines.setdefault(int(r['line']), []).append(r['key'])
    assert tuple(tuple(lines[k]) for k in sorted(lines)) == constants_layout()


def test_every_key_is_described():
    """Each key of the table has a row in the page's sections that say what
    it means (the first cell names it)."""
    with open(DOC, encoding='utf-8') as f:
        text = f.read()
    prose = text[text.index(gen_constants_doc.END):]
    described = set()
    for line in prose.splitlines():
        if line.startswith('| `'):
            described.update(re.findall(r'`([A-Za-z0-9_]+)`', line.split('|')[1]))
    missing = [r['key'] for r in gen_constants_doc.rows() if r['key'] not in described]
    assert not missing, missing


# the fields a SESSION row declares (cable_constants_keys.h's CABLE_CK_DECL_)
SESSION_EXTRA = {'IRS': ['irs', 'irs_name']}
# the session's other bookkeeping fields (cable_constants.h, after the keys)
SESSION_OTHER = ['origin_ndim', 'origin_nbc', 'origin_nint', 'origin_ips', 'ignored']


def test_engine_reads_no_session_field():
    """continuation/, equations/, bc/ and graphics/ read only the engine's
    part of cable_constants: no file that names the constants (a
    cable_constants or the engine handle's cc->c) reads a SESSION row's
    field.  constants_check.c checks every field of a struct filled by hand
    (terminated strings) and is the one exception."""
    fields = list(SESSION_OTHER)
    for r in gen_constants_doc.rows():
        if r['who'] == 'SESSION' and r['kind'] != 'NAMES':
            fields += SESSION_EXTRA.get(r['key'], [r['field']])
    assert 'sv' in fields and 'e' in fields and 'iid' in fields
    pat = re.compile(r'(\bc|cc->c|f->c|crun|\bk)(->|\.)(%s)\b' % '|'.join(fields))
    hits = []
    for folder in ('continuation', 'equations', 'bc', 'graphics'):
        for name in sorted(os.listdir(os.path.join(ROOT, folder))):
            if not name.endswith('.c') or name == 'constants_check.c':
                continue
            with open(os.path.join(ROOT, folder, name), encoding='utf-8') as f:
                text = f.read()
            if 'cable_constants' not in text and 'cc->c' not in text:
                continue
            hits += ['%s/%s:%d' % (folder, name, text[:m.start()].count('\n') + 1) for m in pat.finditer(text)]
    assert not hits, hits
