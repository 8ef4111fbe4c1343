# SPDX-License-Identifier: GPL-3.0-or-later
"""Post-processing of the scenes in runs/: tables computed from named
solutions only (nothing here runs during continuation).  The numerical
analysis of one solution (Lk, writhe, knot type, tube distance, pressure,
axis self-passages) is C (cable._cable); what is done with it is here.

  branch_points(r, T=(lo, hi), kind='double')   branch points chosen by what they are (sol['kind'])
  branch_point(r, T=(lo, hi), kind='simple')    exactly one of them
  compare('table.txt', rows, ref=sol, notes=[...])
  overlap_free(result)
  branch_table('table.txt', result, paper={...}, title='...')
  mirror_table(pairs)
"""

__all__ = ['COMPARE_T_TOL', 'bp_kind', 'fail', 'branch_points', 'branch_point',
           'branch_passages', 'compare', 'overlap_free', 'branch_table',
           'mirror_table']

import math
import os

from . import _cable
from ._cable import CableError
from .atomic import write_text as write_atomic
from .errors import CableTypeError, CableValueError
from .results import Result, Solution

# A UZ label lies at the target T to the engine's location accuracy: the
# arclength of a located user zero converges to EPSS |DS| (1e-7 x DSMAX 5 in
# the knot scenes), so T is off by well under 1e-6; 1e-5 (relative above
# |T| = 1) leaves a margin and is still far below the T spacing of distinct
# stored points.
COMPARE_T_TOL = 1e-5


def _analyze(sol):
    br, i = sol.branch
    return _cable.analyze(br, i)


def _stab(sol):
    """The Morse index of a braid solution (analyze(sol, STAB=1); a knot
    computed with eps13 free is taken as braid_knot_sym, doc/stability.md S7)."""
    br, i = sol.branch
    return _cable.analyze(br, i, 1)


_STAB_HEADER = ('# Morse index (STAB=1, doc/stability.md S7): the number of independent '
                'admissible variations\n'
                '#   that lower the energy; zero: eigenvalues within rounding of 0; '
                'stable = index 0 and no zero eigenvalue\n')


def _stab_line(head, s, st):
    sig = st['sigma'][:3]
    return ('STAB %s  T = %12.6f  index %2d  zero %d  sigma = %s  %s\n'
            % (head, s['T'], st['index'], st['nzero'], ' '.join('%.4g' % x for x in sig),
               'stable' if st['index'] == 0 and st['nzero'] == 0 else 'unstable'))


def _knot_text(a):
    return '%s%s' % ('right ' if a['hand'] > 0 else 'left ' if a['hand'] < 0 else '', a['knot'])


# ---- branch points by what they are ---------------------------------------------------

def bp_kind(sol):
    """The branch point's kind as the detector recorded it
    (cable_solution.bp_kind): 'simple', 'double' or 'pair'; '' for a solution
    read from an s-file (the file does not store it)."""
    return sol.kind


def fail(message):
    """fail('text'): stop the script with that message (a CableError; in
    Python a scene may equally raise it itself)."""
    if not isinstance(message, str):
        raise CableTypeError('fail() takes the message as a string')
    raise CableError(message)


def branch_points(result, T=None, kind=None):
    """The branch points of a result whose T lies in the window T = (lo, hi)
    (None: any) and whose kind is 'simple', 'double' or 'pair' (None: any), in branch
    order."""
    out = []
    for s in result('BP'):
        if T is not None and not (min(T) <= s['T'] <= max(T)):
            continue
        if kind is not None and bp_kind(s) != kind:
            continue
        out.append(s)
    return out


def branch_point(result, T, kind=None):
    """The one branch point of the result in the T window (lo, hi) of the
    given kind; a CableError listing what is there when there is not exactly
    one."""
    found = branch_points(result, T=T, kind=kind)
    if len(found) != 1:
        have = ', '.join('LAB %d at T = %.6g (%s)' % (s.LAB, s['T'], bp_kind(s))
                         for s in result('BP')) or 'none'
        raise CableValueError('%d %sbranch points with T in [%g, %g] (the branch has: %s)'
                              % (len(found), kind + ' ' if kind else '', min(T), max(T), have))
    return found[0]


# ---- self-passages of the braid axis along a branch ---------------------------------------

def branch_passages(br, upto):
    """Self-passages of the braid axis between consecutive labelled solutions
    0..upto of engine branch br (axis_passages.h).  Per interval only the net
    signed number is trusted: parts that pass and come back between two
    labels, or a straight-line homotopy that is no longer faithful (at folds),
    give events of both signs that cancel.  Returns (passes, net, mixed, tau,
    net_iv): the sum of |net| over the intervals, the signed sum (equal to
    (Lk(end) - Lk(start))/2), the intervals with events of both signs, and per
    interval the homotopy parameter of its first passage (nan: none) and its
    net count."""
    passes = net = mixed = 0
    tau, net_iv = [], []
    for i in range(min(upto, br.nsol - 1)):
        count, n, t = _cable.passages(br, i, br, i + 1)
        passes += abs(n)
        net += n
        mixed += count > abs(n)
        tau.append(t if n != 0 else math.nan)
        net_iv.append(n)
    return passes, net, mixed, tau, net_iv


# ---- compare --------------------------------------------------------------------------

def _at_target_t(t, target):
    return abs(t - target) <= COMPARE_T_TOL * max(1.0, abs(target))


def _pick(x, t_target, f_target, row):
    """(solution, number of UZ labels at T_target, which one was taken)."""
    if isinstance(x, Solution):
        if not _at_target_t(x['T'], t_target):
            raise CableValueError('compare: row %d: label %d has T = %.10g, not the target T = '
                                  '%.10g'
                                  % (row, x.LAB, x['T'], t_target))
        return x, 1, 1
    if not isinstance(x, Result):
        raise CableTypeError('compare: row %d: the second entry must be a result or a solution'
                             % row)
    best, nuz, k = None, 0, 0
    for s in x():
        if s.TY != 'UZ' or not _at_target_t(s['T'], t_target):
            continue
        nuz += 1
        if best is None or abs(s['F'] - f_target) < abs(best['F'] - f_target):
            best, k = s, nuz
    if best is None:
        raise CableValueError("compare: row %d: no UZ label at T = %.10g on that result (run it "
                              "with UZR={'T': %.10g})"
                              % (row, t_target, t_target))
    return best, nuz, k


_COMPARE_HEADER = """\
# point: the paper's point; T: its torque; F: paper and cable; rel: |dF|/F.  The cable point is
#   the UZ label at the paper's T on that branch whose F is nearest the paper's (uz: which of
#   the branch's UZ labels at that T was taken, of how many)
# Lk = Tw + Wr of the contact-curve ribbon; dLk/2: (Lk - Lk_ref)/2 against the unbuckled
#   reference, the net number of self-passages of the braid axis that Lk implies;
# pass: self-passages of the braid axis counted along the branch from its start to the point
#   (edges of the axis polyline that pass through each other between consecutive labels), and
#   their signed sum in brackets, which must equal dLk/2; '*': between some labels the axis
#   passed both ways (those cancel and are not counted)
# Lk_tube: Lk minus the writhe of the companion knot's minimal diagram (handedness x crossing
#   number for a torus knot: +3 right trefoil, -3 left), the paper's 'linking number', quoted
#   in brackets; pmin: minimum contact force per length;
# dmin: closest approach of non-adjacent strand centrelines / Delta (< 1: tubes overlap);
# err: discretisation-error estimate of the stored solution
"""


def _is_number(x):
    return isinstance(x, (int, float)) and not isinstance(x, bool)


def compare(runner, file, rows, ref=None, notes=(), stab=False):
    """Writes (atomically) and prints the comparison of computed solutions
    with target values; returns one dict per row (name, LAB, T, F, T_paper,
    F_paper, rel, uz_at_T, uz_chosen, Lk, lk_in_tube, lk_paper, dLk_half,
    passes, passes_net, passes_mixed, knot, hand, crossings, pmin, dmin, err;
    with stab=True also index, nzero, sigma: the Morse index, written in a
    block of 'STAB' lines after the table).

    rows: [[name, x, T_target, F_target, Lk_target(, ref)], ...]: x a result
    (of its UZ labels at T_target the one whose F is nearest F_target) or a
    solution at T_target; ref a solution of the unbuckled branch, for
    (Lk - Lk_ref)/2.  notes: lines written after the table."""
    if not isinstance(file, str) or not isinstance(rows, (list, tuple)):
        raise CableTypeError("compare('file', [[name, result, T_target, F_target, Lk_target], "
                             "...], ref=sol)")
    if ref is not None and not isinstance(ref, Solution):
        raise CableTypeError('ref: ref must be a solution')
    if not isinstance(notes, (list, tuple)) or not all(isinstance(n, str) for n in notes):
        raise CableTypeError('notes: notes must be a list of strings')
    lk_ref = _analyze(ref)['Lk'] if ref is not None else math.nan
    out = [_COMPARE_HEADER,
           '%-5s %4s %5s %12s %12s %14s %9s %9s %5s %9s %15s %-22s %11s %7s %9s\n'
           % ('point', 'LAB', 'uz', 'T', 'F_paper', 'F_cable', 'rel', 'Lk', 'dLk/2', 'pass',
              'Lk_tube(paper)',
              'braid axis', 'pmin', 'dmin', 'err')]
    result = []
    for k, row in enumerate(rows, 1):
        ok = (isinstance(row, (list, tuple)) and len(row) in (5, 6) and isinstance(row[0], str)
              and all(_is_number(v) for v in row[2:5]))
        if not ok:
            raise CableTypeError('compare: row %d must be [name, result or solution, T_target, '
                                 'F_target, Lk_target'
                                 '(, reference solution)]' % k)
        name, x, t_t, f_t, lk_t = row[:5]
        lref = lk_ref
        if len(row) == 6:
            if not isinstance(row[5], Solution):
                raise CableTypeError('compare: row %d: the reference must be a solution' % k)
            lref = _analyze(row[5])['Lk']
        s, nuz, chosen = _pick(x, t_t, f_t, k)
        a = _analyze(s)
        rel = abs(s['F'] - f_t) / abs(f_t)
        dlk = (a['Lk'] - lref) / 2 if not math.isnan(lref) else math.nan
        br, i = s.branch
        passes, net, mixed, _, _ = branch_passages(br, i)
        knot = _knot_text(a)
        out.append('%-5s %4d %5s %12.6f %12.6f %14.7f %9.2e %9.5f %5.1f %9s %15s %-22s %11.4g '
                   '%7.3f %9.2e\n'
                   % (name, s.LAB, '%d/%d' % (chosen, nuz), s['T'], f_t, s['F'], rel, a['Lk'], dlk,
                      '%d (%d)%s' % (passes, net, '*' if mixed else ''),
                      '%.4g (%.4g)' % (a['lk_in_tube'], lk_t), knot, a['pmin'], a['dmin'],
                      a['err']))
        result.append({'name': name, 'LAB': s.LAB, 'T': s['T'], 'F': s['F'], 'T_paper': t_t,
                       'F_paper': f_t,
                       'rel': rel, 'uz_at_T': nuz, 'uz_chosen': chosen, 'Lk': a['Lk'],
                       'lk_in_tube': a['lk_in_tube'], 'lk_paper': lk_t, 'dLk_half': dlk,
                       'passes': passes,
                       'passes_net': net, 'passes_mixed': mixed, 'knot': a['knot'],
                       'hand': a['hand'],
                       'crossings': a['crossings'], 'pmin': a['pmin'], 'dmin': a['dmin'],
                       'err': a['err'],
                       'solution': s})
        if stab:
            st = _stab(s)
            result[-1].update(index=st['index'], nzero=st['nzero'], sigma=list(st['sigma']))
    if stab and result:
        out.append('\n' + _STAB_HEADER)
        out.extend(_stab_line('%-6s LAB %4d' % (d['name'], d['LAB']), d['solution'], d)
                   for d in result)
    if notes:
        out.append('\n')
        out.extend(n + '\n' for n in notes)
    text = ''.join(out)
    write_atomic(file, text)
    print(text, end='')
    return result


# ---- overlap_free -----------------------------------------------------------------------

def _free_stretches(t, d, tau):
    """The stretches where d > 1 along samples (t[i], d[i]) in branch order:
    [T_from, T_to, T_lo, T_hi, to_end, to_passage]; an end between two samples
    is the linear interpolant's crossing of d = 1; tau[i] (not nan): the axis
    passes through itself between samples i and i+1 at that fraction of the
    way, which ends a stretch (and begins the next) there."""
    out = []
    cur = None

    def close(t_end, end, passage):
        cur[1] = t_end
        cur[2] = min(cur[2], t_end)
        cur[3] = max(cur[3], t_end)
        cur[4], cur[5] = end, passage
        out.append(list(cur))

    n = len(t)
    for i in range(n):
        free_now = d[i] > 1.0
        free_before = i > 0 and d[i - 1] > 1.0
        if i > 0 and free_now != free_before:
            cross = t[i - 1] + (1.0 - d[i - 1]) * (t[i] - t[i - 1]) / (d[i] - d[i - 1])
        else:
            cross = t[i]
        if free_before and free_now and not math.isnan(tau[i - 1]):
            tp = t[i - 1] + tau[i - 1] * (t[i] - t[i - 1])
            close(tp, 0, 1)
            cur = [tp, tp, tp, tp, 0, 0]
        if free_now and not free_before:
            cur = [cross, cross, cross, cross, 0, 0]
        if free_now:
            cur[2] = min(cur[2], t[i])
            cur[3] = max(cur[3], t[i])
        if not free_now and free_before:
            close(cross, 0, 0)
        elif free_now and i == n - 1:
            close(t[i], 1, 0)
    return out


def overlap_free(result):
    """For each branch of the result, in branch order, the stretches
    [T_from, T_to, T_lo, T_hi, to_end, to_passage] where the strand tubes do
    not overlap (dmin > 1), judged at the labelled solutions: T at the ends,
    the T range covered (a fold inside turns T back), 1 when the branch ends
    inside the stretch, 1 when it ends where the braid axis passes through
    itself between two labels.  An end between two labels is interpolated
    linearly in dmin, so its accuracy is the label spacing (NPR)."""
    if not isinstance(result, Result):
        raise CableTypeError('overlap_free(result) takes one result')
    out = []
    for br in result.branches:
        _, _, _, tau, _ = branch_passages(br, br.nsol - 1)
        t = [info[4][_t_index(br)] for info in br.labels()]
        d = [_cable.tube_dmin(br, i) for i in range(br.nsol)]
        out.extend(_free_stretches(t, d, tau))
    return out


def _t_index(br):
    names = br.parnames
    if 'T' not in names:
        raise CableValueError('the branch has no parameter T (not a braid problem)')
    return names.index('T')


# ---- branch_table ---------------------------------------------------------------------

_PAPER_KEYS = ("paper: keys are 'knot' (a string), 'Lk', 'T', 'F' (numbers), 'linked', "
               "'psign' (True/False)")


def _paper(p):
    if p is None:
        return {}
    if not isinstance(p, dict):
        raise CableTypeError("paper: paper={'knot': 'right trefoil', 'Lk': 3, 'linked': False, "
                             "'psign': True, "
                             "'T': .., 'F': ..}")
    for k, v in p.items():
        ok = ((k == 'knot' and isinstance(v, str)) or (k in ('Lk', 'T', 'F') and _is_number(v))
              or (k in ('linked', 'psign') and isinstance(v, (bool, int, float))))
        if not ok:
            raise CableValueError('%s: %s' % (k, _PAPER_KEYS))
    return p


def _lk_closed(a):
    """Lk rounded to the integer (link) or half-integer (knot) a closed ribbon has."""
    return math.floor(a['Lk']) + 0.5 if a['closure_sign'] < 0 else float(round(a['Lk']))


def _linked(a):
    """-1 unknown, 0 not linked, 1 linked inside the tube around the axis."""
    return -1 if math.isnan(a['lk_in_tube']) else int(round(a['lk_in_tube']) != 0)


def _agree(yes):
    return 'yes' if yes else 'NO'


def _g(x):
    """C's %g."""
    return '%g' % x


def _positions(what, xs, n):
    s = what
    if n == 0:
        s += ' none'
    s += ''.join(' %.5f' % x for x in xs)
    if n > len(xs):
        s += ' ... (%d in all)' % n
    return s + '\n'


def _table_value(what, x, target):
    s = '%-30s %-42.10f ' % (what, x)
    if target is not None:
        return s + '%-16.10g rel %.1e\n' % (target, abs(x - target) / abs(target))
    return s + '-\n'


def _table_point(s, a, p):
    kt = _knot_text(a)
    link = a['closure_sign'] > 0
    lk_in = _linked(a)
    lkc = _lk_closed(a)
    out = ['%-30s %-42s %-16s %s\n' % ('quantity', 'cable', 'paper', 'agree'),
           _table_value('T = T1 = -T2', s['T'], p.get('T')),
           _table_value('F', s['F'], p.get('F'))]
    buf = '%s (Lk - %s = %.1e)' % (_g(lkc), _g(lkc), a['Lk'] - lkc)
    out.append('%-30s %-42s %-16s %s\n'
               % ('Lk (an integer for a link)' if link else 'Lk (a half-integer for a knot)',
                                          buf, _g(p['Lk']) if 'Lk' in p else '-',
                                          _agree(lkc == p['Lk']) if 'Lk' in p else ''))
    out.append('%-30s %.6f, %.6f\n' % ('Tw, Wr', a['Tw'], a['Wr']))
    out.append('%-30s %-42s %-16s %s\n'
               % ('braid axis', '%s (crossing number %d)' % (kt, a['crossings']),
                                          p.get('knot', '-'), _agree(kt == p['knot'])
                                          if 'knot' in p else ''))
    buf = '%s (Lk_tube = %.4g)' % ('unknown' if lk_in < 0 else 'yes' if lk_in else 'no',
                                   a['lk_in_tube'])
    out.append('%-30s %-42s %-16s %s\n' % ('strands linked inside tube', buf,
                                          ('yes' if p['linked'] else 'no') if 'linked' in p
                                          else '-',
                                          _agree(lk_in == bool(p['linked'])) if 'linked' in p
                                          else ''))
    buf = '%s: %d on strand 1, %d on strand 2' % ('yes' if a['psign'] or a['psign2'] else 'no',
                                                  a['psign'],
                                                  a['psign2'])
    out.append('%-30s %-42s %-16s %s\n' % ('contact pressure changes sign', buf,
                                          ('yes' if p['psign'] else 'no') if 'psign' in p else '-',
                                          _agree((a['psign'] > 0) == bool(p['psign']))
                                          if 'psign' in p else ''))
    out.append('%-30s %s\n' % ('pmin', '%.6g (p1 in [%.6g, %.6g], p2 in [%.6g, %.6g])'
                               % (min(a['pmin1'], a['pmin2']), a['pmin1'], a['pmax1'], a['pmin2'],
                                  a['pmax2'])))
    out.append('%-30s %.4f (axis %.4f)\n' % ('dmin', a['dmin'], a['axis_dmin']))
    out.append('%-30s %.6g (%.4f / Delta)\n' % ('max curvature of the axis', a['axis_kappa_max'],
                                                a['axis_kappa_max'] * s['Delta']))
    if link:
        out.append('%-30s %.6f, %.6f (mod 2 pi; 0: closed)\n'
                   % ('material closure xi1, xi2', a['closure'],
                                                                a['closure2']))
    else:
        out.append('%-30s %.6f (mod 2 pi)\n' % ('material closure', a['closure']))
    out.append('%-30s %.2e\n' % ('first-integral drift', a['drift']))
    out.append('%-30s %.2e\n' % ('error estimate', a['err']) if a['err'] >= 0 else '%-30s -\n'
               % 'error estimate')
    out.append(_positions('p1 changes sign at s        =', a['psign_s1'], a['psign']))
    out.append(_positions('p2 changes sign at sigma    =', a['psign_sigma2'], a['psign2']))
    out.append(_positions('p2 changes sign at s        =', a['psign_s2'], a['psign2']))
    return out


def _table_row(s, a, why):
    head = '%4d %-2s %13.7f %13.6f ' % (s.LAB, s.TY, s['T'], s['F'])
    if a is None:
        return head + 'not analysable: %s\n' % why
    lk_in = _linked(a)
    err = '%9.2e' % a['err'] if a['err'] >= 0 else '%9s' % '-'
    return head + '%10.6f %-18s %8.4f %-6s %11.5g %11.5g %3d %3d %7.4f %8.4f %s\n' % (
        a['Lk'], _knot_text(a), a['lk_in_tube'], '?' if lk_in < 0 else 'yes' if lk_in else 'no',
        a['pmin1'],
        a['pmin2'], a['psign'], a['psign2'], a['dmin'], a['overlap_length'], err)


_TABLE_INTRO = (
    '# Every labelled solution of the branch (%d), analysed as analyze() and `cable '
    'analyze` do.\n'
    "# T = T1(0) = -T2(0) (the paper's T1 = -T2, t10 = -t20; PAR 'T').  Sign "
    'convention: T1 = -C1 (omega1~ - w01)\n'
    "#   is minus strand 1's twisting moment and T2 = C2 (Omega1~/sigma' - w02) is "
    "strand 2's, so T > 0 means\n"
    '#   both strands carry the twisting moment -T about their own tangents '
    '(doc/braid-boundary-conditions.md).\n'
    '# F = |F|, the braid force; Lk = Tw + Wr of the contact-curve ribbon (integer '
    'for a link, half-integer for a knot).\n'
    '# axis: knot type of the braid axis (Alexander polynomial and signature of a '
    'projection, knot_type.h).\n'
    "# Lk_tube: Lk minus the writhe of the axis's minimal diagram; the two strands "
    'are linked inside the tube\n'
    "#   around the axis when it is not 0 ('linked').\n"
    '# p1, p2: contact force per unit length on strand 1, strand 2 (< 0: the strands '
    'must be held together);\n'
    '#   np1, np2: their sign changes along the braid, at the s (arclength of strand '
    '1) and sigma (of strand 2)\n'
    '#   listed at the end.  dmin: closest approach of non-adjacent strand '
    'centrelines / Delta (< 1: the tubes\n'
    '#   overlap), overlap: length in s where they do; err: discretisation-error '
    'estimate.\n'
    "# The paper's values are comparison targets, never inputs: the final knot type "
    'and the reported point are\n'
    '#   decided from the branch alone.\n'
    '\n')


def _same_type(a, b):
    return a['knot'] == b['knot'] and a['hand'] == b['hand']


def branch_table(runner, file, result, paper=None, title=None, stab=False):
    """Analyzes every labelled solution of the result, decides from the branch
    alone the knot type its axis settles into (that of its last analysable
    solution) and the reported point (the first solution of that final
    stretch whose tubes do not overlap), writes (atomically) and prints the
    table (stab=True: and the Morse index of the reported point, a 'STAB' line
    at the end).  Returns the reported point's label (None: no
    solution)."""
    if not isinstance(file, str) or not isinstance(result, Result):
        raise CableTypeError("branch_table('file', result, paper={...}, title='...') takes a file "
                             "name and a result")
    p = _paper(paper)
    if title is not None and not isinstance(title, str):
        raise CableTypeError('title: title must be a string')
    sols = result()
    an, why = [], []
    for s in sols:
        try:
            an.append(_analyze(s))
            why.append(None)
        # an axis passing through itself has no knot type: a row, not an error
        except CableError as e:
            an.append(None)
            why.append(_cable_status_text(e))
    n = len(sols)
    last = n - 1
    while last >= 0 and an[last] is None:
        last -= 1
    out = []
    if title:
        out.append('# %s\n' % title)
    out.append(_TABLE_INTRO % n)
    rep = None
    if last < 0:
        out.append('no labelled solution could be analysed\n')
    else:
        first = last
        for i in range(last - 1, -1, -1):
            if an[i] is None:
                continue
            if not _same_type(an[i], an[last]):
                break
            first = i
        rep = next((i for i in range(first, last + 1) if an[i] is not None
                    and an[i]['dmin'] > 1.0), None)
        nst = sum(1 for i in range(first, last + 1) if an[i] is not None)
        out.append('final knot type of the braid axis (decided from the branch): %s\n'
                   % _knot_text(an[last]))
        out.append('  the type of its last labelled solution, LAB %d; the last %d analysed '
                   'labelled solutions\n'
                   '  (LAB %d-%d, T from %.5f to %.5f) all have it\n'
                   % (sols[last].LAB, nst, sols[first].LAB, sols[last].LAB, sols[first]['T'],
                      sols[last]['T']))
        if rep is not None:
            out.append('reported point: LAB %d, the first of them whose tubes do not overlap '
                       '(dmin > 1)\n\n'
                       % sols[rep].LAB)
        else:
            rep = first
            for i in range(first, last + 1):
                if an[i] is not None and an[i]['dmin'] > an[rep]['dmin']:
                    rep = i
            out.append('reported point: none of them is free of overlap; LAB %d, the one with the '
                       'largest dmin\n\n'
                       % sols[rep].LAB)
        out.extend(_table_point(sols[rep], an[rep], p))
    out.append('\n%4s %-2s %13s %13s %10s %-18s %8s %-6s %11s %11s %3s %3s %7s %8s %9s\n'
               % ('LAB', 'TY', 'T', 'F', 'Lk', 'axis', 'Lk_tube', 'linked', 'p1min', 'p2min',
                  'np1', 'np2', 'dmin',
                  'overlap', 'err'))
    out.extend(_table_row(s, a, w) for s, a, w in zip(sols, an, why))
    out.append('\n# where the contact pressure changes sign: p1 at s (strand 1), p2 at sigma '
               '(strand 2)\n')
    for s, a in zip(sols, an):
        if a is None:
            continue
        out.append(_positions('LAB %4d  p1 at s     =' % s.LAB, a['psign_s1'], a['psign']))
        out.append(_positions('          p2 at sigma =', a['psign_sigma2'], a['psign2']))
    if stab and rep is not None:
        # the reported point's index only: one index costs O(N^3), N = 5 (4 NTST + 1)
        # (2005 at the link scenes' NTST 100), seconds per label (doc/stability.md S7.6)
        out.append('\n' + _STAB_HEADER)
        out.append(_stab_line('reported LAB %4d %-2s' % (sols[rep].LAB, sols[rep].TY), sols[rep],
                              _stab(sols[rep])))
    text = ''.join(out)
    write_atomic(file, text)
    print(text, end='')
    return sols[rep].LAB if rep is not None else None


def _cable_status_text(e):
    msg = str(e)
    i = msg.rfind('(')
    return msg[i + 1:-1] if i >= 0 and msg.endswith(')') else msg


# ---- mirror tables --------------------------------------------------------------------

def mirror_table(pairs):
    """The mirror image against the original at -T: for each (name, mirrored,
    original) the labelled points paired in order up to the shorter branch
    (a run's end, EP after its first point, is left out: the two arms end at
    different steps).  Returns one line per pair: the number of pairs, max
    |T_lh + T_rh|, max |F_lh - F_rh| and the largest F."""
    lines = []
    for name, lh, rh in pairs:
        a, b = lh(), rh()
        pts = [(x, y) for i, (x, y) in enumerate(zip(a, b)) if i == 0
               or (x.TY != 'EP' and y.TY != 'EP')]
        dt = max((abs(x['T'] + y['T']) for x, y in pts), default=0.0)
        df = max((abs(x['F'] - y['F']) for x, y in pts), default=0.0)
        fmax = max((x['F'] for x, _ in pts), default=0.0)
        lines.append('%-9s %3d pairs  max |T_lh + T_rh| = %.2e  max |F_lh - F_rh| = %.2e  (F <= '
                     '%.1f)'
                     % (name, len(pts), dt, df, max(fmax, 0.0)))
    return lines
