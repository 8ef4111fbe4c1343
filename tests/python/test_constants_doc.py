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
