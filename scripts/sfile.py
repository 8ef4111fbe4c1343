"""Minimal reader of cable's s-files (AUTO fort.8 layout, doc/output-formats.md).

read_sfile(path) -> list of dicts {lab, itp, ntst, ncol, ndim, t, u, par}
with t an (ntpl,) array, u an (ntpl, ndim) array and par an (npar,) array.
"""
import numpy as np


def read_sfile(path):
    with open(path) as f:
        lines = f.read().split('\n')
    out = []
    i = 0
    while i < len(lines):
        h = lines[i].split()
        if len(h) < 12:
            i += 1
            continue
        hv = [int(x) for x in h]
        itp, lab, nfpr, ntpl, nar, nrowpr, ntst, ncol, npar = (
            hv[2], hv[3], hv[4], hv[6], hv[7], hv[8], hv[9], hv[10], hv[11])
        block = lines[i + 1:i + 1 + nrowpr]
        i += 1 + nrowpr
        nums = ' '.join(block).replace('D', 'E').split()
        vals = np.array([float(x) for x in nums])
        ndim = nar - 1
        sol = vals[:ntpl * nar].reshape(ntpl, nar)
        rows_sol = ((ndim + 1) + 6) // 7 * ntpl
        rows_par = (npar + 6) // 7
        rest = vals[ntpl * nar:]
        # with the direction: nfpr indices, nfpr tangent components, ntpl*ndim tangent
        if nrowpr > rows_sol + rows_par:
            rest = rest[2 * nfpr + ntpl * ndim:]
        par = rest[:npar]
        out.append({'lab': lab, 'itp': itp, 'ntst': ntst, 'ncol': ncol, 'ndim': ndim,
                    't': sol[:, 0].copy(), 'u': sol[:, 1:].copy(), 'par': par})
    return out
