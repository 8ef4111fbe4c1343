#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Generate the API misuse test from the public headers (doc/api.md, Contracts).

    gen_api_misuse.py OUT.inc [LIBCABLE.so]

Reads every function declared CABLE_API in include/cable/*.h and writes C code
(included by tests/api/api_generated.c) that calls each function once per
pointer argument with that argument NULL and every other argument valid (the
fixtures of api_generated.c), and checks the documented answer: a status
(CABLE_ERR_NULL with a message in the cable_error when one is passed), NULL,
a neutral value, or for an optional argument only that nothing crashed.

The output also lists the functions found in the headers, those that got
cases, and the functions libcable.so exports (nm -D): the test fails when an
exported or declared function has no case, so a new entry point cannot be
forgotten; and the generator fails when a declaration cannot be parsed or an
argument type has no fixture (add it to FIXTURE below)."""
import glob
import os
import re
import subprocess
import sys

# cable's one atomic writer (python/cable/atomic.py), loaded as a file: the
# package itself needs the extension this build has not made yet
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'python', 'cable'))
sys.dont_write_bytecode = True
from atomic import write_text  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# A valid value of each argument type (the fixtures of tests/api/api_generated.c);
# None: no valid value is at hand (the argument is then always NULL).
FIXTURE = {
    'cable_session *': 'f->session', 'const cable_session *': 'f->session',
    'const cable_session_options *': '&f->sopt', 'cable_session_options *': '&f->sopt',
    'const cable_run_args *': '&f->args',
    'cable_branch **': '&f->branch_out',
    'cable_branch *const *': 'f->branches',
    'cable_branch ***': '&f->list_out',
    'cable_branch *': 'f->branch', 'const cable_branch *': 'f->branch',
    'cable_aufile *': 'fx_writer(f)', 'const cable_aufile *': 'fx_writer(f)',
    'cable_aufile_options *': '&f->aopt', 'const cable_aufile_options *': '&f->aopt',
    'int *': '&f->i', 'double *': 'f->d', 'const double *': 'f->d',
    'char *': 'f->buf', 'const char **': '&f->sptr',
    'const char *const *': 'f->strs',
    'cable_constants *': '&f->c', 'const cable_constants *': '&f->c',
    'const cable_constants **': '&f->cptr', 'const cable_names **': '&f->nptr',
    'cable_names *': '&f->names', 'const cable_names *': '&f->names',
    'const cable_problem *': 'f->pb', 'const cable_problem **': '&f->pb_out',
    'cable_error *': '&f->err', 'const cable_error *': '&f->err',
    'cable_solution *': 'f->sol', 'const cable_solution *': 'f->sol',
    'cable_sfile *': 'f->sf', 'const cable_sfile *': 'f->sf',
    'cable_bfile *': 'f->bf', 'const cable_bfile_branch *': '&f->bf->branch[0]',
    'cable_cont *': 'f->cc', 'const cable_cont *': 'f->cc', 'cable_cont **': '&f->cc_out',
    'cable_session **': '&f->session_out', 'void *': 'f',
    'cable_solution **': '&f->sol_out', 'cable_fold **': '&f->fold_out', 'cable_bpcont **': '&f->bpc_out',
    'const cable_sink *': '&f->sink',
    'cable_constants_resolve_fn *': 'fx_resolve', 'void *': None,
    'cable_fold *': 'f->fold', 'const cable_fold *': 'f->fold',
    'cable_braid_analysis *': '&f->ba', 'const cable_braid_analysis *': '&f->ba',
    'const cable_braid_analysis *const *': 'f->bas',
    'cable_tube_distance_result *': '&f->tube', 'cable_axis_passages *': '&f->ap',
    'cable_strands *': '&f->strands', 'cable_stab_result *': '&f->stab',
    'FILE *': 'f->devnull',
    'const cable_plot_annotation *': 'f->marks', 'const cable_render_options *': '&f->ropt',
    # no valid module at hand without a compiler run or a plug-in file
    'cable_plugin *': None, 'const cable_plugin *': None,
    'cable_autoeq *': None, 'const cable_autoeq *': None,
    # no branch point of a BVP among the fixtures (Bratu has none)
    'cable_bpcont *': None, 'const cable_bpcont *': None,
    # the branch list's output array (NULL: only the count)
    'cable_branch_dir *': None,
}

# Valid values of string arguments, by argument name, then by function.
STRING = {
    'dir': '"tests/tmp/api_gen"', 'name': '"gen"', 'path': '"tests/tmp/api_gen/c.gen"',
    'text': '"NTST=5"', 'keyvalue': '"NTST=5"', 'spec': '"1"', 'tok': '"1.5"', 'key': '"NTST"',
    'file': '"f"', 'fmt': '"x"', 'type': '"b"', 'src': '"tests/tmp/no/such.f90"', 'dat': '""',
    'origin': '"gen"', 'x': '"PAR(1)"', 'y': '"L2-NORM"', 'title': '"t"',
    'out': '"tests/tmp/api_gen/gen.svg"', 'vtp': '"tests/tmp/api_gen/gen.vtp"',
    'ply': '"tests/tmp/api_gen/gen.ply"',
}
STRING_FOR = {
    ('cable_sfile_read', 'path'): '"tests/tmp/api_gen/s.gen"',
    ('cable_bfile_read', 'path'): '"tests/tmp/api_gen/b.gen"',
    ('cable_plugin_open', 'path'): '"tests/tmp/no/such.so"',
    ('cable_plugin_open_npar', 'path'): '"tests/tmp/no/such.so"',
    ('cable_render_solution', 'out'): '"tests/tmp/api_gen/gen.png"',
    ('cable_names_par_index', 'name'): '"lambda"',
    ('cable_problem_builtin', 'name'): '"bratu"',
    ('cable_plot_files', 'dir'): '"tests/tmp/api_gen"',
}
ARRAY_FOR = {('cable_plot_files', 'bfiles'): 'f->bfiles'}

# Integer arguments by name (counts match the one-element fixture arrays).
INT = {
    'n': '1', 'nbranch': '1', 'nfiles': '1', 'nmarks': '1', 'npar': '1', 'ndim': '1',
    'i': '0', 'sol_index': '-1', 'lab': '1', 'relabel': '0', 'append': '0', 'ntst': '10',
    'status': 'CABLE_ERR_IO', 'line': '1', 'width': '19', 'digits': '10', 'expdigits': '3',
    'npar_max': '36', 'err_par': '-1', 'from_stpnt': '1', 'ibr': '1', 'first_label': '1',
    'iplt': '0', 'itp': '6', 'nbc': '0', 'nint': '0',
}
INT_FOR = {('cable_braid_tube_distance_solution', 'n'): '0', ('cable_solution_create', 'nfpr'): '1'}

# What a NULL argument gives, by function: 'status' (CABLE_ERR_NULL, the
# default for int), 'neg' (a documented negative value), 'null' (the default
# for pointers), 'nonnull' (a message or ""), 'zero', 'nonpos', 'nan' (the
# default for double), 'any' (void functions: nothing to check but survival).
RESULT = {
    'cable_braid_first_integral_drift': 'neg', 'cable_braid_axis_same_type': 'zero', 'cable_braid_branch_settled': 'neg',
    'cable_aufile_last_label': 'nonpos', 'cable_aufile_last_branch': 'nonpos',
    'cable_aufile_parse_double': 'neg', 'cable_sfile_count': 'zero',
    'cable_autoeq_was_built': 'zero', 'cable_constants_key_known': 'zero',
    'cable_constants_key_known_for': 'zero', 'cable_cont_error': 'nonnull',
    'cable_error_set': 'value:CABLE_ERR_IO', 'cable_error_format': 'nonnull',
    'cable_names_par_index': 'neg', 'cable_names_u_index': 'neg', 'cable_type_code': 'zero',
    'cable_label_spec_parse': 'neg', 'cable_plugin_path': 'nonnull',
    'cable_problem_validate': 'neg', 'cable_branch_number': 'zero', 'cable_branch_npoints': 'zero',
    'cable_branch_nsolutions': 'zero', 'cable_solution_measure': 'any',
    'cable_autoeq_find': 'neg', 'cable_bp_kind_code': 'zero', 'cable_branch_end_status': 'zero',
    'cable_cont_branches': 'neg', 'cable_cont_note': 'nonnull', 'cable_session_nknown': 'zero',
    'cable_branch_switch_directions': 'neg',
}

# Arguments that may be NULL (documented): the call must survive, its result
# is not checked.
OPTIONAL = {
    'cable_braid_pressure_at': {'sigma'},
    'cable_aufile_open': {'dir', 'names', 'opt', 'err'},
    'cable_aufile_checkpoint': {'err'}, 'cable_aufile_close': {'err'},
    'cable_sfile_read': {'err'}, 'cable_sfile_find': {'err'}, 'cable_sfile_resolve_irs': {'err'},
    'cable_bfile_read': {'err'}, 'cable_stability_index': {'err'},
    'cable_session_info': {'err'},
    'cable_braid_solution_curves': {'r1', 'r2', 'c', 'p1', 'p2', 'sigma'},
    'cable_autoeq_find': {'dir'}, 'cable_autoeq_open': {'err'},
    'cable_autoeq_problem': {'c', 'dat', 'err'},
    'cable_constants_parse_file': {'names', 'parnames', 'err'},
    'cable_constants_parse_string': {'name', 'names', 'parnames', 'err'},
    'cable_constants_parse_file_for': {'pb', 'names', 'err'},
    'cable_constants_parse_file_resolve': {'e', 'ctx', 'names', 'err'},
    'cable_constants_parse_string_for': {'name', 'pb', 'names', 'err'},
    'cable_constants_parse_override': {'names', 'parnames', 'err'},
    'cable_constants_parse_override_for': {'pb', 'names', 'err'},
    'cable_constants_key_known_for': {'pb'},
    'cable_cont_check': {'err'}, 'cable_cont_alloc': {'status'},
    'cable_cont_set_start': {'start'}, 'cable_cont_run': {'sink', 'next_label'},
    'cable_cont_test_functions': {'det_sign', 'sv1', 'sv2'},
    'cable_cont_branches': {'out', 'order'}, 'cable_cont_add_known_point': {'name'},
    'cable_error_set': {'e', 'file', 'key', 'fmt'},
    'cable_fold_alloc': {'status', 'msg'},
    'cable_names_par_index': {'n', 'parnames'}, 'cable_names_fill': {'parnames', 'unames'},
    'cable_label_spec_parse': {'type', 'nth'},
    'cable_plot_files': {'dir', 'x', 'y', 'marks', 'title', 'err'},
    'cable_render_solution': {'o', 'out', 'vtp', 'ply', 'err'},
    'cable_plugin_open': {'err'}, 'cable_plugin_open_npar': {'err'},
    'cable_problem_validate': {'origin', 'err'},
    'cable_problem_prepare': {'err'},
    'cable_session_alloc': {'opt'}, 'cable_session_create': {'opt', 'err'},
    'cable_cont_create': {'err'}, 'cable_solution_create': {'err'}, 'cable_fold_create': {'err'},
    'cable_bpcont_create': {'err'}, 'cable_fold_starting_data': {'err'}, 'cable_bpcont_starting_data': {'err'}, 'cable_cont_set_error_handler': {'ctx'},
    'cable_session_run': {'err'}, 'cable_session_load': {'err'}, 'cable_session_save': {'err'},
    'cable_session_loadbd': {'err'}, 'cable_session_transform': {'err'},
    'cable_session_transform_files': {'err'},
    'cable_session_constants': {'c', 'names', 'e', 'err'},
    'cable_session_path': {'type'}, 'cable_session_add_known': {'err'},
    'cable_branch_switch_directions': {'out', 'order'},
}

# Functions that take their handle over (free it): given a fresh one.
CONSUMES = {'cable_aufile_close': 'w'}

# Functions whose calls change process-wide state: listed, called once by
# the hand-written part of the test (tests/api/api_generated.c), not here.
HAND = {'cable_pictures_cleanup', 'cable_blas_single_thread'}

# What frees a returned object (a constructor that succeeded with an optional
# argument NULL).
FREE_RESULT = {
    'cable_aufile *': 'cable_aufile_abort', 'cable_sfile *': 'cable_sfile_free',
    'cable_bfile *': 'cable_bfile_free', 'cable_cont *': 'cable_cont_free',
    'cable_fold *': 'cable_fold_free', 'cable_plugin *': 'cable_plugin_close',
    'cable_autoeq *': 'cable_autoeq_close', 'cable_session *': 'cable_session_free',
    'cable_solution *': 'cable_solution_free',
}


def norm_type(t):
    t = ' '.join(t.replace('struct ', '').split())
    t = re.sub(r'\s*\*\s*', ' *', t)          # "char*" / "char *" -> "char *"
    t = re.sub(r'\* (?=\*)', '*', t)         # "* *" -> "**"
    t = t.replace('*const *', '*const *')
    return t.strip()


def parse_headers():
    funcs, ndecl = [], 0
    for h in sorted(glob.glob(os.path.join(ROOT, 'include/cable/*.h'))):
        text = re.sub(r'/\*.*?\*/', ' ', open(h).read(), flags=re.S)
        text = re.sub(r'//[^\n]*', ' ', text)
        text = '\n'.join(l for l in text.split('\n') if not l.lstrip().startswith('#'))
        ndecl += len(re.findall(r'\bCABLE_API\b', text))
        for m in re.finditer(r'\bCABLE_API\s+([^;{()]*?)\(([^;{]*?)\)\s*(?:__attribute__\s*\(\(.*?\)\))?\s*;',
                             text, flags=re.S):
            head = ' '.join(m.group(1).split())
            name = re.search(r'(\w+)$', head).group(1)
            ret = norm_type(head[:-len(name)])
            params = []
            body = ' '.join(m.group(2).split())
            if body not in ('void', ''):
                for p in body.split(','):
                    p = p.strip()
                    if p == '...':
                        continue
                    pm = re.match(r'(.*?)(\w+)$', p)
                    params.append((norm_type(pm.group(1)), pm.group(2)))
            funcs.append((os.path.basename(h), ret, name, params))
    if ndecl != len(funcs):
        sys.exit('gen_api_misuse.py: %d CABLE_API declarations but %d parsed' % (ndecl, len(funcs)))
    return funcs


def exported(lib):
    if not lib:
        return None
    out = subprocess.run(['nm', '-D', '--defined-only', lib], capture_output=True, text=True, check=True).stdout
    return sorted(l.split()[2] for l in out.splitlines() if len(l.split()) == 3 and l.split()[1] == 'T')


def valid_arg(fn, ptype, pname, fresh):
    if '*' not in ptype:
        if ptype in ('size_t', 'unsigned long'):
            return 'sizeof f->buf'
        if ptype == 'double':
            return '0.5'
        return INT_FOR.get((fn, pname), INT.get(pname, '0'))
    if (fn, pname) in ARRAY_FOR:
        return ARRAY_FOR[(fn, pname)]
    if ptype == 'const char *':
        return STRING_FOR.get((fn, pname), STRING.get(pname, '"gen"'))
    if ptype not in FIXTURE:
        sys.exit('gen_api_misuse.py: %s: no fixture for argument type "%s" (%s): add one' % (fn, ptype, pname))
    v = FIXTURE[ptype]
    if v and v.startswith('fx_writer'):
        fresh.append(pname)
    return v


CASES = []


def c_string(s):
    return '"' + s.replace('\\', '\\\\').replace('"', '\\"') + '"'


def emit_case(out, hdr, ret, fn, params, k):
    pname = params[k][1]
    optional = pname in OPTIONAL.get(fn, set())
    fresh, args = [], []
    for j, (pt, pn) in enumerate(params):
        if j == k:
            args.append('NULL')
        else:
            v = valid_arg(fn, pt, pn, fresh)
            args.append(v if v is not None else 'NULL')
    label = '%s(%s = NULL)%s' % (fn, pname, ' [optional]' if optional else '')
    has_err = any(pt in ('cable_error *',) for pt, _ in params) and params[k][0] != 'cable_error *'
    out.append('static void gen_case_%d(fx *f) /* %s */' % (len(CASES), hdr))
    out.append('{')
    CASES.append(label)
    out.append('  fx_reset(f);')
    for pn in fresh:
        out.append('  cable_aufile *w_%s = fx_writer(f);' % pn)
    args = ['w_%s' % params[j][1] if params[j][1] in fresh and j != k else a for j, a in enumerate(args)]
    call = '%s(%s)' % (fn, ', '.join(args))
    kind = 'any' if optional else RESULT.get(fn)
    if ret == 'void':
        out.append('  %s;' % call)
        kind = 'any'
    elif ret == 'cable_sink':
        out.append('  cable_sink r = %s;' % call)
        out.append('  api_check(%s, !r.point && !r.solution && !r.diag);' % c_string(label + ': a sink without callbacks'))
        kind = None
    elif ret in ('int', 'long'):
        out.append('  int r = %s;' % call)
        kind = kind or 'status'
    elif ret == 'double':
        out.append('  double r = %s;' % call)
        kind = kind or 'nan'
    else:
        out.append('  %s r = %s;' % (ret, call))
        kind = kind or 'null'
        if ret in FREE_RESULT:
            out.append('  if (r) %s(r);' % FREE_RESULT[ret])
    lab = c_string(label)
    if kind == 'status':
        out.append('  api_expect_null_status(f, %s, r, %d);' % (lab, 1 if has_err else 0))
    elif kind == 'neg':
        out.append('  api_check(%s, r < 0);' % c_string(label + ': negative'))
    elif kind == 'nonpos':
        out.append('  api_check(%s, r <= 0);' % c_string(label + ': <= 0'))
    elif kind == 'zero':
        out.append('  api_check_int(%s, r, 0);' % lab)
    elif kind == 'null':
        out.append('  api_check(%s, r == NULL);' % c_string(label + ': NULL'))
    elif kind == 'nonnull':
        out.append('  api_check(%s, r != NULL);' % c_string(label + ': a string'))
    elif kind == 'nan':
        out.append('  api_check(%s, isnan(r));' % c_string(label + ': NaN'))
    elif kind and kind.startswith('value:'):
        out.append('  api_check_int(%s, r, %s);' % (lab, kind[6:]))
    elif kind == 'any':
        if ret not in ('void',):
            out.append('  (void)r;')
        out.append('  api_check(%s, 1);' % c_string(label + ': returned'))
    for pn in fresh:
        if CONSUMES.get(fn) != pn:
            out.append('  cable_aufile_abort(w_%s);' % pn)
    out.append('  fx_after(f);')
    out.append('}')


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    funcs = parse_headers()
    exp = exported(sys.argv[2] if len(sys.argv) > 2 else None)
    out = ['/* Generated by scripts/gen_api_misuse.py from the headers in include/cable/: do not edit. */']
    covered = []
    for hdr, ret, fn, params in funcs:
        if fn in HAND:
            continue
        ptrs = [k for k, (pt, _) in enumerate(params) if '*' in pt]
        for k in ptrs:
            emit_case(out, hdr, ret, fn, params, k)
        covered.append((fn, len(ptrs)))
    out.append('/* the cases in order, and what each calls */')
    out.append('static void (*const gen_case_fn[])(fx *) = {')
    for k in range(len(CASES)):
        out.append('  gen_case_%d,' % k)
    out.append('};')
    out.append('static const char *const gen_case_name[] = {')
    for lab in CASES:
        out.append('  %s,' % c_string(lab))
    out.append('};')
    out.append('')
    out.append('/* every CABLE_API function of the headers: name, pointer arguments (cases) */')
    out.append('static const struct gen_fn { const char *name; int ncases; } gen_header_functions[] = {')
    for hdr, ret, fn, params in funcs:
        n = sum('*' in pt for pt, _ in params)
        out.append('  {%s, %d},' % (c_string(fn), n))
    out.append('};')
    out.append('/* the functions gen_cases() calls (HAND ones: the hand-written part) */')
    out.append('static const char *const gen_covered[] = {')
    for fn, _ in covered:
        out.append('  %s,' % c_string(fn))
    for fn in sorted(HAND):
        out.append('  %s,   /* by hand */' % c_string(fn))
    out.append('};')
    out.append('/* the functions libcable.so exports (nm -D at generation; NULL ends) */')
    out.append('static const char *const gen_exported[] = {')
    for s in exp or []:
        out.append('  %s,' % c_string(s))
    out.append('  NULL};')
    out.append('static const int gen_exported_known = %d;' % (1 if exp is not None else 0))
    write_text(sys.argv[1], '\n'.join(out) + '\n')


if __name__ == '__main__':
    main()
