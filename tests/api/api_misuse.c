/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Misuse of every public entry point (include/cable/): NULL handles and
 * arguments, calls in the wrong order, invalid sizes, failed constructors.
 * Each must give a status (or NULL, or a documented neutral value) and never
 * crash; `make asan` runs this program under AddressSanitizer and UBSan.
 * Written against the public headers only and linked with libcable.so. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "api_check.h"
#include "cable/cable.h"

static const char *const bratu_text = "IPS = 4, ICP = ['lambda'], NTST = 10, NCOL = 3, DS = 0.1, NMX = 5\n";

static void misuse_status_error(void)
{
  api_check("cable_status_message(unknown code) is a message", strcmp(cable_status_message(12345), "unknown status") == 0);
  api_check("cable_status_name(unknown code)", strcmp(cable_status_name(-12345), "CABLE_STATUS_UNKNOWN") == 0);
  /* every code has its own message */
  const int codes[] = {CABLE_ERR_ALLOC, CABLE_ERR_INPUT, CABLE_ERR_NEWTON, CABLE_ERR_DSMIN, CABLE_ERR_CALLBACK,
                       CABLE_ERR_RECOVERABLE, CABLE_ERR_LINSOLVE, CABLE_ERR_KINSOL, CABLE_ERR_IO, CABLE_ERR_PARSE,
                       CABLE_ERR_PLUGIN, CABLE_ERR_NOTFOUND, CABLE_ERR_UNSUPPORTED, CABLE_ERR_NONFINITE,
                       CABLE_ERR_SWITCH, CABLE_ERR_NULL, CABLE_ERR_STATE, CABLE_ERR_SIZE, CABLE_ERR_RANGE};
  int n = (int)(sizeof codes / sizeof codes[0]), distinct = 1;
  for (int i = 0; i < n; i++)
    for (int j = 0; j < i; j++)
      if (codes[i] == codes[j] || strcmp(cable_status_message(codes[i]), cable_status_message(codes[j])) == 0)
        distinct = 0;
  api_check("status codes and their messages are distinct", distinct);
  cable_error_clear(NULL);
  api_check_int("cable_error_set(NULL, ...) returns the status", cable_error_set(NULL, CABLE_ERR_IO, "f", 1, "k", "x"),
                CABLE_ERR_IO);
  char buf[64];
  api_check("cable_error_format(NULL error)", strcmp(cable_error_format(NULL, buf, sizeof buf), "") == 0);
  cable_error e;
  cable_error_set(&e, CABLE_ERR_IO, "f", 1, "k", "x");
  api_check("cable_error_format(NULL buffer) is a string", cable_error_format(&e, NULL, 0) != NULL);
}

static void misuse_problem_names(void)
{
  api_check("cable_problem_builtin(NULL)", cable_problem_builtin(NULL) == NULL);
  api_check("cable_problem_builtin(unknown)", cable_problem_builtin("nosuch") == NULL);
  api_check("cable_problem_builtin_name(-1)", cable_problem_builtin_name(-1) == NULL);
  api_check("cable_problem_builtin_name(1000)", cable_problem_builtin_name(1000) == NULL);
  const cable_problem *inst = (const cable_problem *)1;
  cable_error err;
  api_check_int("cable_problem_prepare(NULL problem)", cable_problem_prepare(NULL, NULL, 1, &inst, &err), CABLE_ERR_NULL);
  api_check("  *instance is NULL after a failure", inst == NULL);
  api_check_int("cable_problem_prepare(NULL instance pointer)",
                cable_problem_prepare(cable_problem_builtin("bratu"), NULL, 1, NULL, NULL), CABLE_ERR_NULL);
  cable_problem_release(NULL, NULL);
  cable_problem_release(cable_problem_builtin("bratu"), NULL);
  api_check("cable_problem_key_find(NULL)", cable_problem_key_find(NULL, "TORUS") == NULL);
  api_check("cable_problem_key_find(NULL name)", cable_problem_key_find(cable_problem_builtin("braid_knot"), NULL) == NULL);

  cable_names_init(NULL);
  api_check_int("cable_names_par_index(NULL, NULL)", cable_names_par_index(NULL, NULL, NULL, 0), -1);
  api_check_int("cable_names_u_index(NULL, NULL)", cable_names_u_index(NULL, NULL), -1);
  cable_names_fill(NULL, NULL, 3, NULL, 3);
  api_check("cable_type_name(unknown)", cable_type_name(12345) != NULL);
  api_check_int("cable_type_code(NULL)", cable_type_code(NULL), 0);
  int ty = 0, nth = 0;
  api_check_int("cable_label_spec_parse(NULL)", cable_label_spec_parse(NULL, &ty, &nth), -1);
  api_check_int("cable_label_spec_parse(spec, NULL outputs: optional)", cable_label_spec_parse("BP1", NULL, NULL), 0);
  api_check_int("cable_type_base(INT_MIN + 6) keeps the sign", cable_type_base(-2147483642), -2);
}

static void misuse_constants(void)
{
  cable_constants c;
  cable_error err;
  cable_constants_init(NULL);
  cable_constants_init(&c);
  api_check("cable_constants_key(NULL constants)", isnan(cable_constants_key(NULL, cable_problem_builtin("braid_knot"), "TORUS")));
  api_check("cable_constants_key(NULL problem)", isnan(cable_constants_key(&c, NULL, "TORUS")));
  api_check("cable_constants_parse_file(NULL path)", cable_constants_parse_file(NULL, &c, NULL, NULL, 0, &err) < 0);
  api_check_int("cable_constants_parse_file(missing file)",
                cable_constants_parse_file("tests/tmp/no/such/c.file", &c, NULL, NULL, 0, &err), CABLE_ERR_IO);
  api_check("cable_constants_parse_file(NULL constants)", cable_constants_parse_file("x", NULL, NULL, NULL, 0, &err) < 0);
  api_check("cable_constants_parse_string(NULL text)", cable_constants_parse_string("x", NULL, &c, NULL, NULL, 0, &err) < 0);
  api_check("cable_constants_parse_string(NULL constants)",
            cable_constants_parse_string("x", "NTST=5", NULL, NULL, NULL, 0, &err) < 0);
  api_check("cable_constants_parse_string(NULL name)", cable_constants_parse_string(NULL, "NTST=5", &c, NULL, NULL, 0, NULL) == 0);
  api_check("cable_constants_parse_override(NULL)", cable_constants_parse_override(NULL, &c, NULL, NULL, 0, &err) < 0);
  api_check("cable_constants_parse_override(NULL constants)",
            cable_constants_parse_override("NTST=5", NULL, NULL, NULL, 0, &err) < 0);
  api_check("cable_constants_parse_file_for(NULL path)", cable_constants_parse_file_for(NULL, NULL, &c, NULL, &err) < 0);
  api_check("cable_constants_parse_string_for(NULL text)",
            cable_constants_parse_string_for("x", NULL, NULL, &c, NULL, &err) < 0);
  api_check("cable_constants_parse_override_for(NULL)", cable_constants_parse_override_for(NULL, NULL, &c, NULL, &err) < 0);
  cable_constants_take_problem_dims(NULL, 1, 1, 1);
  api_check_int("cable_constants_key_known(NULL)", cable_constants_key_known(NULL), 0);
  api_check_int("cable_constants_key_known_for(NULL, NULL)", cable_constants_key_known_for(NULL, NULL), 0);
}

static void misuse_solution(void)
{
  api_check("cable_solution_alloc(ndim 0)", cable_solution_alloc(0, 10, 4, 36, 1) == NULL);
  api_check("cable_solution_alloc(negative ntst)", cable_solution_alloc(2, -5, 4, 36, 1) == NULL);
  api_check("cable_solution_alloc(negative nfpr)", cable_solution_alloc(2, 5, 4, 36, -1) == NULL);
  api_check("cable_solution_alloc(sizes that overflow)", cable_solution_alloc(1 << 30, 1 << 30, 7, 36, 1) == NULL);
  cable_solution_free(NULL);
  cable_solution *a = cable_solution_alloc(2, 5, 4, 36, 1), *b = cable_solution_alloc(2, 6, 4, 36, 1);
  api_check_int("cable_solution_copy(NULL, NULL)", cable_solution_copy(NULL, NULL), CABLE_ERR_NULL);
  api_check_int("cable_solution_copy(other sizes)", cable_solution_copy(a, b), CABLE_ERR_SIZE);
  api_check("cable_solution_clone(NULL)", cable_solution_clone(NULL) == NULL);
  api_check_int("cable_solution_npts(NULL)", cable_solution_npts(NULL), 0);
  api_check("cable_solution_measure(NULL) gives the L2-norm passed in", cable_solution_measure(NULL, 3, 1.5) == 1.5);
  cable_solution_free(a);
  cable_solution_free(b);
}

static void misuse_cont(void)
{
  const cable_problem *pb = cable_problem_builtin("bratu");
  cable_constants c;
  cable_error err;
  cable_constants_parse_string_for("c.bratu", bratu_text, pb, &c, NULL, &err);
  int st = 0;
  api_check_int("cable_cont_check(NULL, NULL)", cable_cont_check(NULL, NULL, &err), CABLE_ERR_NULL);
  cable_cont *cc = cable_cont_alloc(NULL, &c, &st);
  api_check("cable_cont_alloc(NULL problem): NULL", cc == NULL);
  api_check_int("  status", st, CABLE_ERR_NULL);
  api_check("cable_cont_alloc(NULL constants, NULL status)", cable_cont_alloc(pb, NULL, NULL) == NULL);
  /* the case: NTST = -5, then set_start and step on what came back */
  cable_constants bad = c;
  bad.ntst = -5;
  cc = cable_cont_alloc(pb, &bad, &st);
  api_check("NTST = -5: the constructor returns NULL (nothing half-built)", cc == NULL);
  api_check_int("  status", st, CABLE_ERR_INPUT);
  api_check("  cable_cont_check says why", cable_cont_check(pb, &bad, &err) == CABLE_ERR_INPUT && strstr(err.msg, "NTST") != NULL);
  api_check_int("  cable_cont_set_start on it: CABLE_ERR_NULL", cable_cont_set_start(cc, NULL), CABLE_ERR_NULL);
  api_check_int("  cable_cont_set_mesh on it: CABLE_ERR_NULL", cable_cont_set_mesh(cc, NULL), CABLE_ERR_NULL);
  api_check_int("  cable_cont_step on it: CABLE_ERR_NULL", cable_cont_step(cc), CABLE_ERR_NULL);
  int next = -1;
  api_check_int("  cable_cont_run on it: CABLE_ERR_NULL", cable_cont_run(cc, NULL, 1, 7, &next), CABLE_ERR_NULL);
  api_check_int("  next label unchanged", next, 7);
  api_check("  cable_cont_point(NULL)", cable_cont_point(NULL) == NULL);
  api_check("  cable_cont_solution(NULL)", cable_cont_solution(NULL) == NULL);
  api_check("  cable_cont_error(NULL) is a message", cable_cont_error(NULL) != NULL && cable_cont_error(NULL)[0]);
  int det = 5;
  double sv1 = 5, sv2 = 5;
  cable_cont_test_functions(NULL, &det, &sv1, &sv2);
  api_check("  cable_cont_test_functions(NULL) gives zeros", det == 0 && sv1 == 0 && sv2 == 0);
  cable_cont_free(NULL);
  bad = c;
  bad.ncol = 9;
  api_check("NCOL = 9: NULL", cable_cont_alloc(pb, &bad, &st) == NULL && st == CABLE_ERR_INPUT);
  bad = c;
  bad.nicp = 0;
  api_check("no ICP: NULL", cable_cont_alloc(pb, &bad, &st) == NULL && st == CABLE_ERR_INPUT);
  cable_problem broken = *pb;
  broken.abi_version = 1;
  api_check("a problem of another ABI: NULL", cable_cont_alloc(&broken, &c, &st) == NULL && st == CABLE_ERR_INPUT);
  /* wrong order on a good handle */
  cc = cable_cont_alloc(pb, &c, &st);
  api_check("a good handle", cc != NULL);
  api_check_int("step before set_start: CABLE_ERR_STATE", cable_cont_step(cc), CABLE_ERR_STATE);
  api_check_int("run before set_start: CABLE_ERR_STATE", cable_cont_run(cc, NULL, 1, 1, NULL), CABLE_ERR_STATE);
  api_check("  the handle says so", strstr(cable_cont_error(cc), "set_start") != NULL);
  api_check("point before the first point: NULL", cable_cont_point(cc) == NULL && cable_cont_solution(cc) == NULL);
  /* a restart from a solution of another problem size */
  cable_solution *other = cable_solution_alloc(3, 10, 3, 36, 1);
  api_check("set_start from a solution of another NDIM: an error", cable_cont_set_start(cc, other) < 0);
  cable_solution_free(other);
  api_check_int("set_start from STPNT", cable_cont_set_start(cc, NULL), CABLE_SUCCESS);
  api_check("run with a NULL sink", cable_cont_run(cc, NULL, 1, 1, NULL) > 0);
  api_check("after the run: the last point", cable_cont_point(cc) != NULL && cable_cont_solution(cc) != NULL);
  api_check("step after the end: the end status again", cable_cont_step(cc) > 0);
  cable_cont_free(cc);
  cable_blas_single_thread();
  api_check("cable_blas_single_thread is for applications and may be called", 1);
}

static void misuse_files(void)
{
  cable_error err;
  cable_aufile_options_init(NULL);
  api_check("cable_aufile_open(NULL constants)", cable_aufile_open("tests/tmp", "x", NULL, NULL, NULL, &err) == NULL);
  api_check("cable_aufile_open(NULL name)", cable_aufile_open("tests/tmp", NULL, NULL, NULL, NULL, &err) == NULL);
  cable_aufile_set_constants(NULL, NULL);
  cable_sink s = cable_aufile_sink(NULL);
  api_check("cable_aufile_sink(NULL): a sink without callbacks", !s.point && !s.solution && !s.diag);
  api_check("cable_aufile_last_label(NULL)", cable_aufile_last_label(NULL) <= 0);
  api_check("cable_aufile_last_branch(NULL)", cable_aufile_last_branch(NULL) <= 0);
  api_check_int("cable_aufile_checkpoint(NULL)", cable_aufile_checkpoint(NULL, &err), CABLE_ERR_NULL);
  api_check_int("cable_aufile_close(NULL)", cable_aufile_close(NULL, &err), CABLE_ERR_NULL);
  cable_aufile_abort(NULL);
  api_check("cable_aufile_format_es(NULL buffer)", cable_aufile_format_es(NULL, 1.0, 19, 10, 3) == NULL);
  double v = 7;
  api_check_int("cable_aufile_parse_double(NULL)", cable_aufile_parse_double(NULL, &v), -1);
  api_check_int("cable_aufile_parse_double(NULL out)", cable_aufile_parse_double("1.5", NULL), -1);
  api_check("cable_sfile_read(NULL)", cable_sfile_read(NULL, &err) == NULL);
  api_check("cable_sfile_read(missing)", cable_sfile_read("tests/tmp/no/such/s.x", &err) == NULL && err.status == CABLE_ERR_IO);
  cable_sfile_free(NULL);
  api_check_int("cable_sfile_count(NULL)", cable_sfile_count(NULL), 0);
  api_check("cable_sfile_get(NULL)", cable_sfile_get(NULL, 0) == NULL);
  api_check("cable_sfile_find_label(NULL)", cable_sfile_find_label(NULL, 1) == NULL);
  api_check("cable_sfile_find(NULL)", cable_sfile_find(NULL, "BP1", &err) == NULL);
  cable_constants c;
  cable_constants_init(&c);
  api_check("cable_sfile_resolve_irs(NULL)", cable_sfile_resolve_irs(NULL, &c, &err) < 0);
  cable_sfile_take_err_est(NULL, 3);
  api_check("cable_bfile_read(NULL)", cable_bfile_read(NULL, &err) == NULL);
  cable_bfile_free(NULL);
  api_check("cable_bfile_column(NULL)", cable_bfile_column(NULL, "T") == NULL);

  const cable_problem *pb = NULL;
  api_check("cable_plugin_open(NULL)", cable_plugin_open(NULL, &pb, &err) == NULL && pb == NULL);
  api_check("cable_plugin_open(NULL problem pointer)", cable_plugin_open("x.so", NULL, &err) == NULL);
  api_check("cable_plugin_open_npar(NULL)", cable_plugin_open_npar(NULL, 36, &pb, &err) == NULL);
  cable_plugin_close(NULL);
  api_check("cable_plugin_problem(NULL)", cable_plugin_problem(NULL) == NULL);
  api_check("cable_plugin_path(NULL)", cable_plugin_path(NULL) != NULL);
  api_check_int("cable_problem_validate(NULL)", cable_problem_validate(NULL, 36, NULL, &err), CABLE_ERR_PLUGIN);

  char src[64] = "unchanged";
  api_check("cable_autoeq_find(NULL name)", cable_autoeq_find(NULL, NULL, src, sizeof src) < 0);
  api_check("cable_autoeq_find(NULL path)", cable_autoeq_find(NULL, "bratu", NULL, 0) < 0);
  api_check("cable_autoeq_open(NULL)", cable_autoeq_open(NULL, &err) == NULL);
  api_check("cable_autoeq_open(missing file)", cable_autoeq_open("tests/tmp/no/such.f90", &err) == NULL);
  api_check("cable_autoeq_problem(NULL)", cable_autoeq_problem(NULL, NULL, NULL, &pb, &err) < 0);
  api_check("cable_autoeq_problem(NULL problem pointer)", cable_autoeq_problem(NULL, NULL, NULL, NULL, &err) < 0);
  api_check("cable_autoeq_source(NULL)", cable_autoeq_source(NULL) == NULL);
  api_check("cable_autoeq_module(NULL)", cable_autoeq_module(NULL) == NULL);
  api_check_int("cable_autoeq_was_built(NULL)", cable_autoeq_was_built(NULL), 0);
  cable_autoeq_close(NULL);
}

static void misuse_analysis_pictures(void)
{
  cable_braid_analysis a;
  cable_error err;
  double p1, p2, sg;
  api_check("cable_braid_first_integral_drift(NULL) < 0", cable_braid_first_integral_drift(NULL) < 0);
  api_check("cable_braid_pressure_at(NULL)", cable_braid_pressure_at(NULL, 0.5, &p1, &p2, &sg) < 0);
  api_check("cable_braid_pressure_signs(NULL)", cable_braid_pressure_signs(NULL, &a) < 0);
  api_check("cable_braid_analysis_compute(NULL)", cable_braid_analysis_compute(NULL, &a) < 0);
  /* a solution of another problem (Bratu: NDIM 2) is not a braid */
  cable_solution *s = cable_solution_alloc(2, 5, 3, 36, 1);
  api_check("cable_braid_analysis_compute(a non-braid solution)", cable_braid_analysis_compute(s, &a) < 0);
  api_check("cable_braid_analysis_compute(NULL out)", cable_braid_analysis_compute(s, NULL) < 0);
  api_check("cable_braid_first_integral_drift(a non-braid solution) < 0", cable_braid_first_integral_drift(s) < 0);
  api_check_int("cable_braid_axis_same_type(NULL, NULL)", cable_braid_axis_same_type(NULL, NULL), 0);
  int first = 5;
  api_check_int("cable_braid_branch_settled(NULL, 0)", cable_braid_branch_settled(NULL, 0, &first), -1);
  api_check("cable_plot_files(NULL files)",
            cable_plot_files(NULL, NULL, 1, NULL, NULL, NULL, 0, NULL, "tests/tmp/x.png", &err) < 0);
  api_check("cable_plot_files(NULL output)", cable_plot_files(NULL, NULL, 0, NULL, NULL, NULL, 0, NULL, NULL, &err) < 0);
  api_check("cable_render_solution(NULL)", cable_render_solution(NULL, NULL, "tests/tmp/x.png", NULL, NULL, &err) < 0);
  api_check("cable_render_solution(a non-braid solution)",
            cable_render_solution(s, NULL, "tests/tmp/x.png", NULL, NULL, &err) < 0);
  cable_solution_free(s);
  char buf[8];
  api_check("cable_version_string(NULL buffer)", cable_version_string(NULL, 0) == NULL);
  api_check("cable_version_string(short buffer) is terminated",
            cable_version_string(buf, sizeof buf) == buf && strlen(buf) < sizeof buf);
}

int main(void)
{
  misuse_status_error();
  misuse_problem_names();
  misuse_constants();
  misuse_solution();
  misuse_cont();
  misuse_files();
  misuse_analysis_pictures();
  return api_summary();
}
