# SPDX-License-Identifier: GPL-3.0-or-later
"""Tables of the link readings study (scripts/link_readings.sh; doc/links.md).

Reads the s-files the study wrote and prints, per figure: the labelled points
of both halves of the branch (at the caption's T and the readings' T), F(Delta)
at the caption's T, and the parameter readings.  The captions' T and F are the
comparison targets (the paper's Figs. 12.7-12.9), never inputs of a run.
Usage: /usr/bin/python3 scripts/link_readings_table.py SCRATCH_DIR
(the s-files are read by cable's own loadbd).
"""
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, 'build', 'release', 'python'))
import cable  # noqa: E402

# PAR slots (equations/braid_state.h, 0-based)
T, L2, DELTA, C1, C2, F, H, HAM, DMIN = 0, 2, 4, 9, 10, 15, 17, 19, 21
CAPTIONS = {'fig127': (-11.46623, 364.061, 0.016016913268),
            'fig128': (-14.4933, 633.545, 0.006),
            'fig129': (-14.63829, 946.310, 0.002)}


def labelled(path, types=('UZ',)):
    """The solutions of s-file path of the given types, as {lab, par}."""
    d, base = os.path.split(path)
    if not os.path.exists(path) or not base.startswith('s.'):
        return []
    here = os.getcwd()
    os.chdir(d or '.')
    try:
        result = cable.loadbd(base[2:])
    finally:
        os.chdir(here)
    return [{'lab': s.LAB, 'par': s.PAR.toarray()} for s in result() if s.TY in types]


CABLE = os.path.join(ROOT, 'cable')


def dmin_of(d, sname, lab):
    """closest approach of non-adjacent tube parts / Delta (cable analyze)"""
    out = subprocess.run([CABLE, 'analyze', sname, str(lab)], cwd=d, capture_output=True, text=True)
    m = re.search(r'closest non-adjacent approach ([0-9.eE+-]+) Delta', out.stdout)
    return float(m.group(1)) if m else float('nan')


def row(s, fpub, dmin=None):
    p = s['par']
    return '%6d %14.8f %14.8f %12.4e %14.10g %8.4f %12.6g %12.6g' % (
        s['lab'], p[T], p[F], p[F] / fpub - 1, p[DELTA], p[DMIN] if dmin is None else dmin, p[H], p[HAM])


def main(top):
    head = '%6s %14s %14s %12s %14s %8s %12s %12s' % ('LAB', 'T', 'F', 'F/F_cap-1', 'Delta', 'dmin', 'h', 'Ham')
    for fig, (tpub, fpub, dpub) in CAPTIONS.items():
        d = os.path.join(top, fig)
        if not os.path.isdir(d):
            continue
        print('\n### %s: caption T = %g, F = %g, Delta = %g' % (fig, tpub, fpub, dpub))
        for half in ('mode', 'modeb'):
            names = [n for n in sorted(os.listdir(d)) if n.startswith('s.mode') and
                     (n.endswith('b') == (half == 'modeb'))]
            for n in names:
                print('\nbranch %s (%s half), labelled points:' % (n[2:], 'DS > 0' if half == 'mode' else 'DS < 0'))
                print(head)
                for s in labelled(os.path.join(d, n)):
                    print(row(s, fpub))
        for k in ('', '1', '2'):
            pts = [('s.d%s_%s' % (k, w), s) for w in ('dn', 'up')
                   for s in labelled(os.path.join(d, 's.d%s_%s' % (k, w)))]
            if not pts:
                continue
            pts.sort(key=lambda x: x[1]['par'][DELTA])
            print('\nF(Delta) at T = %g%s:' % (tpub, {'': '', '1': ' (DS > 0 half)', '2': ' (DS < 0 half)'}[k]))
            print(head)
            for name, s in pts:
                print(row(s, fpub, dmin_of(d, name, s['lab'])))
        for n, what in (('s.rc2', 'C1 = C2 = B/(2(1+nu))'), ('s.rl2', 'L2 = 1 - 2 pi Delta')):
            pts = labelled(os.path.join(d, n))
            if pts:
                print('\nreading %s, at T = %g:' % (what, tpub))
                print(head)
                print(row(pts[-1], fpub))


if __name__ == '__main__':
    if len(sys.argv) != 2:
        sys.exit('usage: link_readings_table.py SCRATCH_DIR')
    main(sys.argv[1])
