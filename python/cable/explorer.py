# SPDX-License-Identifier: GPL-3.0-or-later
"""explore(): one command for a family of torus knots or links (doc/explore.md).

    cable explore TORUS=7 HAND=1 Delta=0.0051364907419 Ltot=1.98889 modes=4 [out=DIR]
    python3 -m cable.explorer ...           (the same)
    cable.explore(7, 1, 0.0051364907419, Ltot=1.98889, modes=4)

computes the flat branch of the (p,2) torus knot (p odd) or link (p even) on
both arms (T > 0: 'right', T < 0: 'left'), its branch points, every branch
direction of the first N of them on each arm, and follows each branch to the
fold where it turns back in T (FOLDS of them), a closed loop, a known branch
(a branch point computed before: the session's known points) or the limits
(RL0, RL1, NMX).  Along every branch it finds, between consecutive labelled
solutions, where the braid axis passes through itself (axis_passages.c) and
where the tubes start or stop overlapping (tube_distance.c), and writes into
the output directory:

  b./s./d.NAME     every branch (flat, flat_left, r1, r1_2, l1, ...), c.flat, c.branch
  diagram.png      T against F: the branches, their branch points (filled, numbered),
                   the axis self-passages (x) and the ends of the overlap-free stretches (o)
  table.txt        one row per overlap-free stretch of every branch: its T interval, Lk,
                   the companion knot (the braid axis's type), Lk_tube, the contact
                   pressure's sign, dmin; and per branch how it ended
  table.json       the same rows for programs
  NAME_LAB.png     the 3-D picture of each overlap-free stretch (at its first
                   overlap-free labelled solution) of the bifurcating branches
  log.txt          the engine's log (the command line also prints it)

The directory is built as OUT.partial-PID and renamed to OUT when everything
is written (a directory without that suffix is complete; an existing OUT is
replaced only then).

Switching.  At a branch point the branch directions come from the engine's
algebraic bifurcation equations (BRANCH=k, doc/engine.md "Multiple branch
points"): the explorer asks for them with a one-step run and follows every
direction the start's note lists.  When the equations give no list (they
vanish identically at the D_p-symmetric double points unless the problem
declares its symmetry, as braid_knot and braid_link now do: then one direction
of multiplicity p, followed in Fix(S0)), switch='auto' falls back to the S0-symmetric
formulation (braid_knot_sym / braid_link_sym, eps13 in ICP), on which the
point is simple and has one branch; switch='plain' or 'sym' forces one way.
"""

__all__ = ['explore', 'directions', 'follow', 'stretches', 'turns', 'branch_end', 'FLAT',
           'BRANCH', 'TABLE_FIELDS', 'main']

import ast
import json
import math
import os
import re
import shutil
import sys
import threading
import time

from . import _cable, atomic, plotting, scenes
from .commands import Runner, constant_text
from .errors import CableValueError
from .results import branch_columns

# A run changes the process's current directory: one explore at a time per process.
_LOCK = threading.Lock()

_ICP = {('knot', False): ['T', 'L', 'L2', 'eps21', 'F', 'h', 'Ham'],
        ('knot', True): ['T', 'L', 'L2', 'eps21', 'eps13', 'F', 'h', 'Ham'],
        ('link', False): ['T', 'F', 'h', 'Ham', 'Phi'],
        ('link', True): ['T', 'eps13', 'F', 'h', 'Ham', 'Phi']}

# The flat branch's constants (runs/knot72/c.knot72's numerics): BPs by the
# singular-value test (ISP=2, NSV=2), which sees double points too.
FLAT = {'NTST': 30, 'NCOL': 7, 'IAD': 3, 'JAC': 1, 'ISP': 2, 'ILP': 0, 'NSV': 2,
        'DS': 5.0, 'DSMIN': 1e-6, 'DSMAX': 20.0, 'NMX': 100, 'RL0': -200.0, 'RL1': 200.0,
        'EPSL': 1e-7, 'EPSU': 1e-7, 'EPSS': 1e-7}
# The branches' (c.knot72sym's numerics, with folds located: ILP=1); RL0/RL1
# default to +-max(40, 1.5 max|T| of the followed branch points).
BRANCH = {'NTST': 30, 'NCOL': 7, 'IAD': 3, 'JAC': 1, 'ISW': -1, 'ISP': 2, 'NSV': 2, 'ILP': 1,
          'DS': 0.05, 'DSMIN': 1e-6, 'DSMAX': 10.0, 'PREDICTOR': 2, 'NMX': 400, 'NPR': 2,
          'EPSL': 1e-7, 'EPSU': 1e-7, 'EPSS': 1e-7}

TABLE_FIELDS = ['branch', 'arm', 'bp', 'bp_T', 'bp_F', 'direction', 'ndir', 'formulation', 'end',
                'stretch', 'T_from', 'T_to', 'T_lo', 'T_hi', 'stretch_end', 'LAB', 'T', 'F', 'Lk',
                'companion', 'crossings', 'Lk_tube', 'pressure', 'pmin', 'psign', 'dmin',
                'passages', 'picture']


def _kind(p):
    return 'knot' if p % 2 else 'link'


def _problem(kind, sym):
    return 'braid_%s%s' % (kind, '_sym' if sym else '')


def _write_constants(name, head, consts):
    lines = ['# ' + head] + [constant_text(k, v) for k, v in consts.items()]
    atomic.write_text('c.' + name, '\n'.join(lines) + '\n')


# ---- the branch directions at a branch point -------------------------------------------

def directions(runner, bp, kind):
    """The branch directions at branch point bp on the plain problem, as
    run(bp, ISW=-1, BRANCH=k) follows them (Runner.branches: one switch step
    with the constants file c.branch; directions equivalent under a symmetry
    the problem declares are one entry with their multiplicity, and one
    followed in the problem restricted to Fix(S) is marked restricted): the
    list of dicts; [] when there are none (a simple point: the ordinary
    switch; degenerate equations and no declared symmetry)."""
    try:
        return runner.branches(bp, c='branch', e=_problem(kind, False), ICP=_ICP[(kind, False)])
    except CableValueError:
        return []


def branch_end(result):
    """How a branch ended: 'fold' (its last point is the fold it stopped at),
    'branch point' (a branch point located on it, where it meets another
    branch), 'closed loop', 'known branch: <the point>', 'limits' (RL0/RL1, NMX) or
    'error: <note>'."""
    br = result.branches[0]
    note = br.end_note or ''
    st = br.end_status or ''
    last = result()[-1] if len(result()) else None
    if 'joins a known branch' in note:
        m = re.search(r'is (BP label \d+ of branch \d+)', note)
        return 'known branch: %s' % (m.group(1) if m else 'a known point')
    if 'closed loop' in note:
        return 'closed loop'
    if last is not None and last.TY == 'LP':
        return 'fold'
    if last is not None and last.TY == 'BP' and len(result()) > 1:
        return 'branch point'
    if st in ('CABLE_END_BOUNDS', 'CABLE_END_NMX'):
        return 'limits'
    if st.startswith('CABLE_END'):
        return st[len('CABLE_END_'):].lower()
    return 'error: %s' % (note or st)


def follow(runner, bp, kind, switch='auto', folds=1, sv=None, bp_kind=None, **over):
    """Every branch from branch point bp, with the constants file c.branch:
    [(direction k, n directions, formulation, result, info)], k = 1..n (info:
    the direction's entry of Runner.branches, {} without one).  switch:
    'auto' (the directions the bifurcation equations give on the plain
    problem; when they give none, the S0-symmetric formulation at a double
    point, the plain problem's one switch at a simple one), 'plain' (the plain
    problem always), 'sym' (the S0-symmetric formulation at a double point,
    the plain problem at a simple one, without asking the equations).
    bp_kind: the detector's kind of the point ('double', 'simple', 'pair';
    None: bp.kind, which a solution read from a file does not have).  Each
    branch stops at its FOLDS-th fold (STOP=['LP<folds>']; folds=0: no fold
    stop), a closed loop, a known branch or the limits.  sv: the files' name
    (NAME, NAME_2, ...); over: more constants for the runs."""
    double = (bp_kind if bp_kind is not None else bp.kind) == 'double'
    dirs = directions(runner, bp, kind) if switch in ('auto', 'plain') else []
    n = len(dirs)
    use_sym = double and (switch == 'sym' or (switch == 'auto' and n == 0))
    e = _problem(kind, use_sym)
    out = []
    count = 1 if use_sym else max(n, 1)
    for k in range(1, count + 1):
        kw = dict(over)
        kw.update(c='branch', e=e, ISW=-1, ICP=_ICP[(kind, use_sym)])
        if folds > 0:
            # the fold, or a branch point on the branch: it meets another branch there (the
            # engine's fold test misses some folds of the mode branches, doc/explore.md)
            kw['STOP'] = ['LP%d' % folds, 'BP1']
        if n > 0 and not use_sym:
            kw['BRANCH'] = k
        if sv:
            kw['sv'] = sv if k == 1 else '%s_%d' % (sv, k)
        r = runner.run(bp, **kw)
        info = dirs[k - 1] if n > 0 and not use_sym else {}
        out.append((k, count, e, r, info))
    return out


# ---- events and stretches along a branch ----------------------------------------------

def stretches(result):
    """The overlap-free stretches of a one-branch result and the axis
    self-passages along it.  Returns (stretches, passages): each stretch a
    dict T_from, T_to, T_lo, T_hi, end ('branch end', 'axis passage',
    'overlap' or '') and idx (the indices of its labelled solutions); each
    passage (T, F, net count) interpolated between its two labels at the
    homotopy parameter of the first passage."""
    br = result.branches[0]
    sols = result()
    t = [s['T'] for s in sols]
    f = [s['F'] for s in sols]
    d = [_cable.tube_dmin(br, i) for i in range(br.nsol)]
    _, _, _, tau, net = scenes.branch_passages(br, br.nsol - 1)
    passages = []
    for i, (tt, n) in enumerate(zip(tau, net)):
        if n:
            passages.append((t[i] + tt * (t[i + 1] - t[i]), f[i] + tt * (f[i + 1] - f[i]), n))
    spans = scenes._free_stretches(t, d, tau)
    groups, cur = [], None
    for i in range(len(t)):
        if d[i] > 1.0:
            if cur is None or not (d[i - 1] > 1.0) or not math.isnan(tau[i - 1]):
                cur = [i]
                groups.append(cur)
            else:
                cur.append(i)
        else:
            cur = None
    if len(groups) != len(spans):   # the two walks are the same rule: a mismatch is a bug
        raise CableValueError('explore: %d overlap-free groups but %d stretches'
                              % (len(groups), len(spans)))
    out = []
    for g, sp in zip(groups, spans):
        end = 'branch end' if sp[4] else 'axis passage' if sp[5] else 'overlap'
        out.append({'T_from': sp[0], 'T_to': sp[1], 'T_lo': sp[2], 'T_hi': sp[3], 'end': end,
                    'idx': g})
    return out, passages, d


def turns(result):
    """The T of every point of a one-branch result where T turns back (a
    fold in T, located or not): the middle point of three consecutive points
    whose T steps change sign."""
    t, _ = _columns(result)
    out = []
    for i in range(1, len(t) - 1):
        if (t[i] - t[i - 1]) * (t[i + 1] - t[i]) < 0:
            out.append(t[i])
    return out


def _pressure(a):
    if a['pmin'] > 0:
        return '+'
    if a['pmax1'] < 0:
        return '-'
    return '+-'


def _knot_text(a):
    return scenes._knot_text(a)


def _interp_F(sols, idx_before, T):
    """F at T on the segment of labels idx_before, idx_before+1 (linear)."""
    i = idx_before
    if i + 1 >= len(sols):
        return sols[i]['F']
    t0, t1 = sols[i]['T'], sols[i + 1]['T']
    w = 0.0 if t1 == t0 else (T - t0) / (t1 - t0)
    return sols[i]['F'] + w * (sols[i + 1]['F'] - sols[i]['F'])


# ---- the exploration ---------------------------------------------------------------------

def _split_constants(kw):
    """(flat overrides, branch overrides) from keyword constants: flat_KEY /
    flat.KEY only the flat branch, branch_KEY / branch.KEY only the branches,
    KEY both."""
    flat, branch = {}, {}
    for k, v in kw.items():
        for pre, d in (('flat', flat), ('branch', branch)):
            if k.startswith(pre + '.') or k.startswith(pre + '_'):
                d[k[len(pre) + 1:]] = v
                break
        else:
            flat[k] = v
            branch[k] = v
    return flat, branch


def explore(TORUS, HAND, Delta, Ltot=None, L=None, modes=2, out=None, switch='auto', arms='both',
            folds=1, pictures=True, quiet=False, **constants):
    """Explores the (TORUS,2) family (see the module's text); returns a dict:
    'dir' (the output directory), 'flat' {'right': result, 'left': result},
    'bps' {'right': [...], 'left': [...]} (solutions), 'branches' (a list of
    dicts: name, arm, bp (k), direction, ndir, formulation, end, result,
    stretches, passages), 'rows' (the table's rows), 'seconds'."""
    p, hand = int(TORUS), int(HAND)
    if p < 2 or hand not in (1, -1):
        raise CableValueError('explore: TORUS=p (p >= 2) and HAND=1 or -1')
    if switch not in ('auto', 'plain', 'sym'):
        raise CableValueError("explore: switch='auto', 'plain' or 'sym'")
    if arms not in ('both', 'right', 'left'):
        raise CableValueError("explore: arms='both', 'right' or 'left'")
    kind = _kind(p)
    length = Ltot if kind == 'knot' else L
    if length is None:
        raise CableValueError('explore: the length (%s=...) is needed'
                              % ('Ltot' if kind == 'knot' else 'L'))
    out = os.path.abspath(out or 'explore-%d-%s' % (p, 'right' if hand > 0 else 'left'))
    part = '%s.partial-%d' % (out, os.getpid())
    fo, bo = _split_constants(constants)
    with _LOCK:
        here = os.getcwd()
        if os.path.exists(part):
            shutil.rmtree(part)
        os.makedirs(part)
        try:
            os.chdir(part)
            res = _explore_here(p, hand, kind, float(Delta), float(length), int(modes), switch,
                                arms,
                                int(folds), pictures, fo, bo)
        finally:
            os.chdir(here)
        if os.path.exists(out):
            old = '%s.old-%d' % (out, os.getpid())
            os.rename(out, old)
            os.rename(part, out)
            shutil.rmtree(old)
        else:
            os.rename(part, out)
    res['dir'] = out
    return res


def _explore_here(p, hand, kind, Delta, length, modes, switch, arms, folds, pictures, fo, bo):
    t0 = time.time()
    runner = Runner()
    par = {'Delta': Delta, 'T': 0.0, ('Ltot' if kind == 'knot' else 'L'): length}
    fc = dict(FLAT)
    fc.update({k: v for k, v in fo.items() if k not in ('PAR',)})
    if 'PAR' in fo:
        par.update(fo['PAR'])
    flat_c = {'e': _problem(kind, False), 'NDIM': 21, 'IPS': 4, 'ICP': _ICP[(kind, False)],
              'TORUS': p, 'HAND': hand, 'PAR': par}
    flat_c.update(fc)
    flat_c['STOP'] = ['BP%d' % modes] if modes > 0 else []
    _write_constants('flat', 'the flat branch (cable explore)', flat_c)
    arm_list = [('right', 1), ('left', -1)] if arms == 'both' else \
        [('right', 1)] if arms == 'right' else [('left', -1)]
    flat, bps = {}, {}
    for name, sign in (('right', 1), ('left', -1)):
        r = runner.run(c='flat', e=flat_c['e'], DS=sign * abs(flat_c['DS']),
                       sv='flat' if sign > 0 else 'flat_left')
        flat[name] = r
        bps[name] = [b for b in r('BP') if b['T'] * sign > 0][:modes]
        runner.known(r)
    tmax = max([abs(b['T']) for v in bps.values() for b in v] + [0.0])
    bc = dict(BRANCH)
    bc.update({'RL0': -max(40.0, 1.5 * tmax), 'RL1': max(40.0, 1.5 * tmax)})
    bc.update(bo)
    branch_c = {'NDIM': 21, 'IPS': 4}
    branch_c.update(bc)
    _write_constants('branch', 'the branches from the branch points (cable explore)', branch_c)
    branches = []
    for arm, sign in arm_list:
        for k, bp in enumerate(bps[arm], 1):
            name = '%s%d' % (arm[0], k)
            for j, n, e, r, info in follow(runner, bp, kind, switch, folds, sv=name):
                runner.known(r)
                st, pas, d = stretches(r)
                branches.append({'name': name if j == 1 else '%s_%d' % (name, j), 'arm': arm,
                                 'bp': k, 'bp_sol': bp, 'direction': j, 'ndir': n,
                                 'formulation': e, 'end': branch_end(r), 'result': r,
                                 'stretches': st, 'passages': pas,
                                 'dmin': d, 'turns': turns(r),
                                 'multiplicity': info.get('multiplicity', 1),
                                 'restricted': bool(info.get('restricted', False))})
    rows = _rows(runner, branches, bps, pictures)
    _diagram(flat, bps, branches, p, hand)
    _table(rows, branches, flat, bps, p, hand, Delta, length, kind, switch)
    return {'flat': flat, 'bps': bps, 'branches': branches, 'rows': rows,
            'seconds': time.time() - t0}


def _rows(runner, branches, bps, pictures):
    rows = []
    for b in branches:
        r = b['result']
        sols = r()
        br = r.branches[0]
        lk0 = _cable.analyze(*b['bp_sol'].branch)['Lk']
        base = {'branch': b['name'], 'arm': b['arm'], 'bp': b['bp'], 'bp_T': b['bp_sol']['T'],
                'bp_F': b['bp_sol']['F'], 'direction': b['direction'], 'ndir': b['ndir'],
                'formulation': b['formulation'], 'end': b['end']}
        if not b['stretches']:
            rows.append(dict(base, stretch=0))
            continue
        for s_no, st in enumerate(b['stretches'], 1):
            # the first overlap-free label after the branch point itself (the flat knot)
            at = st['idx'][1] if st['idx'][0] == 0 and len(st['idx']) > 1 else st['idx'][0]
            row = dict(base, stretch=s_no, T_from=st['T_from'], T_to=st['T_to'], T_lo=st['T_lo'],
                       T_hi=st['T_hi'], stretch_end=st['end'], LAB=sols[at].LAB,
                       T=sols[at]['T'], F=sols[at]['F'], dmin=b['dmin'][at])
            try:
                a = _cable.analyze(br, at)
            except _cable.CableError as e:
                row['companion'] = 'not analysable: %s' % e
                rows.append(row)
                continue
            row.update(Lk=a['Lk'], companion=_knot_text(a), crossings=a['crossings'],
                       Lk_tube=a['lk_in_tube'], pressure=_pressure(a), pmin=a['pmin'],
                       psign=a['psign'], passages=round((a['Lk'] - lk0) / 2, 6))
            if pictures:
                pic = '%s_%d.png' % (b['name'], sols[at].LAB)
                runner.render(sols[at], pic)
                row['picture'] = pic
            rows.append(row)
    return rows


def _columns(result):
    """T and F of every point of a one-branch result (its b-file rows)."""
    cols = dict(branch_columns(result.branches[0]))
    return cols['T'], cols['F']


def _diagram(flat, bps, branches, p, hand):
    Figure, FigureCanvasAgg = plotting._matplotlib()
    fig = Figure(figsize=(8, 6))
    FigureCanvasAgg(fig)
    ax = fig.add_subplot(1, 1, 1)
    for name, r in flat.items():
        t, f = _columns(r)
        ax.plot(t, f, 'k-', lw=1.2, label='flat' if name == 'right' else None)
    for arm, v in bps.items():
        for k, b in enumerate(v, 1):
            ax.plot([b['T']], [b['F']], 'ko', ms=5)
            ax.annotate('%s%d' % (arm[0], k), (b['T'], b['F']), textcoords='offset points',
                        xytext=(4, -12), fontsize=8)
    for b in branches:
        t, f = _columns(b['result'])
        line, = ax.plot(t, f, '-', lw=1, label='%s (%s)' % (b['name'], b['end']))
        c = line.get_color()
        for (t, f, n) in b['passages']:
            ax.plot([t], [f], 'x', color=c, ms=7)
        sols = b['result']()
        for st in b['stretches']:
            ends = ((st['T_from'], max(st['idx'][0] - 1, 0)), (st['T_to'], st['idx'][-1]))
            for t_end, i in ends:
                ax.plot([t_end], [_interp_F(sols, i, t_end)], 'o', mfc='none', color=c, ms=6)
    ax.set_xlabel('T')
    ax.set_ylabel('F')
    ax.set_title('(%d,2) torus %s, %s-handed: x axis passes itself, o overlap starts/stops'
                 % (p, _kind(p), 'right' if hand > 0 else 'left'), fontsize=9)
    ax.legend(fontsize=7, loc='best')
    plotting.save(fig, 'diagram.png')


def _form(b):
    """The formulation, with the Fix(S) restriction and the direction's multiplicity."""
    return '%s%s x%d' % (b['formulation'], ' in Fix(S)' if b['restricted'] else '',
                         b['multiplicity'])


def _fmt(v):
    if v is None:
        return '-'
    if isinstance(v, float):
        return '%.6g' % v
    return str(v)


def _table(rows, branches, flat, bps, p, hand, Delta, length, kind, switch):
    lines = ['# cable explore: (%d,2) torus %s, HAND=%d, Delta=%.12g, length=%.12g, switch=%s'
             % (p, kind, hand, Delta, length, switch),
             '# branch points of the flat branch (arm k: T, F, kind)']
    for arm, v in bps.items():
        for k, b in enumerate(v, 1):
            lines.append('#   %s%d  LAB %3d  T = %12.7f  F = %12.6f  %s'
                         % (arm[0], k, b.LAB, b['T'], b['F'], b.kind or '?'))
    lines.append('# branches: name, its branch point, direction j of n, formulation (in Fix(S):'
                 ' followed in')
    lines.append('#   the problem restricted to a declared symmetry; xm: the directions it stands'
                 ' for),')
    lines.append('#   points, end,')
    lines.append('#   the T where it turns back (folds in T, from its points)')
    for b in branches:
        lines.append('#   %-8s %s%d  %d/%d  %-24s %4d  %-12s turns at T = %s'
                     % (b['name'], b['arm'][0], b['bp'], b['direction'], b['ndir'], _form(b),
                        b['result'].branches[0].npt, b['end'],
                        ', '.join('%.6g' % x for x in b['turns']) or '-'))
    lines.append('# rows: one per overlap-free stretch (dmin > 1) of a branch, between axis'
                 ' passages;')
    lines.append('#   T_from..T_to its ends (T_lo..T_hi the T range when a fold is inside),'
                 ' stretch_end')
    lines.append('#   why it ends; LAB, T, F the labelled solution analysed (its first); Lk, the')
    lines.append('#   companion knot (the braid axis), Lk_tube; pressure: + / - / +- the contact'
                 ' pressure')
    lines.append('#   sign (pmin, psign its sign changes); passages: (Lk - Lk_bp)/2')
    lines.append('\t'.join(TABLE_FIELDS))
    for r in rows:
        lines.append('\t'.join(_fmt(r.get(k)) for k in TABLE_FIELDS))
    atomic.write_text('table.txt', '\n'.join(lines) + '\n')
    clean = [{k: r.get(k) for k in TABLE_FIELDS} for r in rows]
    atomic.write_text('table.json', json.dumps({'rows': clean, 'branches': [
        {'name': b['name'], 'arm': b['arm'], 'bp': b['bp'], 'direction': b['direction'],
         'ndir': b['ndir'], 'formulation': b['formulation'], 'end': b['end'],
         'multiplicity': b['multiplicity'], 'restricted': b['restricted'],
         'points': b['result'].branches[0].npt, 'turns': b['turns'],
         'passages': [list(x) for x in b['passages']]} for b in branches]}, indent=1) + '\n')


# ---- command line ----------------------------------------------------------------------

_OWN = ('TORUS', 'HAND', 'Delta', 'Ltot', 'L', 'modes', 'out', 'switch', 'arms', 'folds',
        'pictures')


def _value(text):
    try:
        return ast.literal_eval(text)
    except (ValueError, SyntaxError):
        return text


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if not argv or argv[0] in ('-h', '--help'):
        print('usage: cable explore TORUS=p HAND=+-1 Delta=D (Ltot=L | L=L) [modes=N] [out=DIR]\n'
              '       [switch=auto|plain|sym] [arms=both|right|left] [folds=1] [pictures=0]\n'
              '       [KEY=VALUE | flat.KEY=VALUE | branch.KEY=VALUE ...]   (doc/explore.md)')
        return 0 if argv else 2
    kw = {}
    for a in argv:
        if '=' not in a:
            print('cable explore: %r is not KEY=VALUE' % a, file=sys.stderr)
            return 2
        k, v = a.split('=', 1)
        kw[k] = v if k in ('out', 'switch', 'arms') else _value(v)
    for k in ('TORUS', 'HAND', 'Delta'):
        if k not in kw:
            print('cable explore: %s= is needed' % k, file=sys.stderr)
            return 2
    _cable.blas_single_thread()
    try:
        res = explore(kw.pop('TORUS'), kw.pop('HAND'), kw.pop('Delta'), **kw)
    except (_cable.CableError, ValueError, TypeError) as e:
        print('cable explore: %s' % e, file=sys.stderr)
        return 1
    print('cable explore: %d branches from %d branch points in %.1f s; %s/table.txt, diagram.png'
          % (len(res['branches']), sum(len(v) for v in res['bps'].values()), res['seconds'],
             res['dir']))
    return 0


if __name__ == '__main__':
    sys.exit(main())
