/* SPDX-License-Identifier: GPL-3.0-or-later */
/* cable's picture commands on real output: a bifurcation diagram from a
 * b-file the AUTO writer produced, a rendered braid solution with its
 * exports, and the error paths (missing file, unknown column, not a braid). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cable/cable_analysis.h"
#include "cable/cable_aufile.h"
#include "braid_problems.h"
#include "braid_start.h"
#include "cable/cable_cont.h"
#include "cable/cable_pictures.h"
#include "cable/cable_constants.h"
#include "graphics_text.h"
#include "harness.h"
#include "test_problems.h"

static long file_size(const char *path)
{
  struct stat st;
  return stat(path, &st) == 0 ? (long)st.st_size : -1;
}

static int png_signature(const char *path)
{
  unsigned char sig[8] = {0};
  FILE *f = fopen(path, "rb");
  if (!f) return 0;
  size_t n = fread(sig, 1, 8, f);
  fclose(f);
  return n == 8 && memcmp(sig, "\x89PNG\r\n\x1a\n", 8) == 0;
}

int main(void)
{
  mkdir("tests/tmp", 0755);
  mkdir("tests/tmp/pictures", 0755);
  cable_error err;
  /* a b-file from a real run: the Bratu branch */
  cable_constants c;
  cable_constants_init(&c); c.ips = 4;   /* a boundary-value problem (AUTO's default IPS is 1) */
  c.ntst = 10; c.ncol = 4; c.jac = 1; c.icp[0] = 0; c.nicp = 1;
  c.ds = 0.2; c.dsmin = 1e-5; c.dsmax = 0.5; c.nmx = 20; c.npr = 5; c.ilp = 1;
  cable_constants_take_problem_dims(&c, 2, 2, 0);
  cable_names names;
  cable_names_init(&names);
  const cable_problem *bratu = cable_testproblem_bratu();
  cable_names_fill(&names, bratu->parnames, bratu->npar, bratu->unames, bratu->ndim);
  cable_error_clear(&err);
  cable_aufile *w = cable_aufile_open("tests/tmp/pictures", "bratu", &c, &names, NULL, &err);
  int st;
  cable_cont *cc = cable_cont_alloc(bratu, &c, &st);
  if (st == 0) st = cable_cont_set_start(cc, NULL);
  cable_sink sink = cable_aufile_sink(w);
  if (st == 0) cable_cont_run(cc, &sink, 1, 1, NULL);
  cable_cont_free(cc);
  test_int("b-file written", cable_aufile_close(w, &err), 0);
  const char *files[1] = {"b.bratu"};
  test_int("plot a b-file", cable_plot_files("tests/tmp/pictures", files, 1, NULL, NULL, NULL, 0, "Bratu",
                                             "tests/tmp/pictures/bratu.png", &err), 0);
  test_true("diagram is a PNG", png_signature("tests/tmp/pictures/bratu.png"));
  test_int("plot to SVG", cable_plot_files("tests/tmp/pictures", files, 1, "lambda", "L2-NORM", NULL, 0, NULL,
                                           "tests/tmp/pictures/bratu.svg", &err), 0);
  test_true("SVG written", file_size("tests/tmp/pictures/bratu.svg") > 1000);
  cable_error_clear(&err);
  test_int("unknown column: CABLE_ERR_NOTFOUND", cable_plot_files("tests/tmp/pictures", files, 1, "nosuch", NULL,
                                                                  NULL, 0, NULL, "tests/tmp/pictures/x.png", &err),
           CABLE_ERR_NOTFOUND);
  test_true("unknown column: message names the column", strcmp(err.key, "nosuch") == 0);
  test_true("unknown column: no picture written", file_size("tests/tmp/pictures/x.png") < 0);
  cable_error_clear(&err);
  test_int("plot to an unknown format (.jpg): CABLE_ERR_INPUT",
           cable_plot_files("tests/tmp/pictures", files, 1, NULL, NULL, NULL, 0, NULL, "tests/tmp/pictures/x.jpg", &err),
           CABLE_ERR_INPUT);
  test_true("  the message names the file and o=, and says which suffixes",
            strcmp(err.key, "o") == 0 && strstr(err.msg, ".png or .svg") != NULL);
  test_true("  nothing written", file_size("tests/tmp/pictures/x.jpg") < 0);
  const char *missing[1] = {"b.does_not_exist"};
  cable_error_clear(&err);
  test_true("missing b-file: error", cable_plot_files("tests/tmp/pictures", missing, 1, NULL, NULL, NULL, 0, NULL,
                                                      "tests/tmp/pictures/y.png", &err) != 0 &&
                                         strstr(err.file, "b.does_not_exist") != NULL);

  /* a converged flat (7,2) knot, rendered and exported */
  braid_start_params sp;
  braid_start_params_init(&sp, BRAID_START_TORUS, 7, +1, 0.0051364907419, 1.98889, 0.0);
  cable_problem pb;
  test_int("torus start", braid_start_prepare(&sp) || braid_problem_instance("braid_knot", &sp, &pb), 0);
  cable_constants_init(&c); c.ips = 4;   /* a boundary-value problem (AUTO's default IPS is 1) */
  c.ntst = 30; c.ncol = 4; c.jac = 1; c.icp[0] = BP_T; c.icp[1] = BP_L; c.icp[2] = BP_L2; c.icp[3] = BP_EPS21;
  c.nicp = 4; c.nmx = 1;
  cc = cable_cont_alloc(&pb, &c, &st);
  if (st == 0) st = cable_cont_set_start(cc, NULL);
  if (st == 0) st = cable_cont_step(cc);
  test_int("flat knot converged", st, 0);
  if (st == 0) {
    cable_render_options o;
    memset(&o, 0, sizeof o);
    o.width = o.height = 200;
    test_int("render a braid solution", cable_render_solution(cable_cont_solution(cc), &o,
                                                              "tests/tmp/pictures/knot.png",
                                                              "tests/tmp/pictures/knot.vtp",
                                                              "tests/tmp/pictures/knot.ply", &err), 0);
    test_true("render: PNG", png_signature("tests/tmp/pictures/knot.png"));
    test_true("render: VTK file", file_size("tests/tmp/pictures/knot.vtp") > 10000);
    test_true("render: PLY file", file_size("tests/tmp/pictures/knot.ply") > 10000);
    /* the strands cable view stores: r2 = r1 + Delta d1 with |d1| = 1, a
       knot (closed 0), radius Delta/2; the pressures at the nodes span the
       range the analysis (cable_braid_analysis_compute) reports for each strand */
    cable_strands cs;
    const cable_solution *sol = cable_cont_solution(cc);
    test_int("strands of a braid solution", cable_solution_strands(sol, &cs), 0);
    double dd = 0, lo1 = INFINITY, hi1 = -INFINITY, lo2 = INFINITY, hi2 = -INFINITY;
    for (int k = 0; k < cs.n; k++) {
      double d2 = 0;
      for (int i = 0; i < 3; i++) d2 += (cs.r2[3 * k + i] - cs.r1[3 * k + i]) * (cs.r2[3 * k + i] - cs.r1[3 * k + i]);
      dd = fmax(dd, fabs(sqrt(d2) - 2 * cs.radius));
      lo1 = fmin(lo1, cs.p1[k]), hi1 = fmax(hi1, cs.p1[k]), lo2 = fmin(lo2, cs.p2[k]), hi2 = fmax(hi2, cs.p2[k]);
    }
    cable_braid_analysis *ba = malloc(sizeof *ba);
    int arc = ba ? cable_braid_analysis_compute(sol, ba) : -1;
    printf("     strands: n %d, | |r2 - r1| - Delta | <= %.2e, p1 %.8g..%.8g (analysis %.8g..%.8g), "
           "p2 %.8g..%.8g (analysis %.8g..%.8g)\n", cs.n, dd, lo1, hi1, arc ? (double)NAN : ba->pmin1, arc ? (double)NAN : ba->pmax1,
           lo2, hi2, arc ? (double)NAN : ba->pmin2, arc ? (double)NAN : ba->pmax2);
    test_true("strands: n = NTST NCOL + 1, a knot, radius Delta/2",
              cs.n == 30 * 4 + 1 && cs.closed == 0 && fabs(cs.radius - 0.5 * 0.0051364907419) < 1e-15);
    test_true("strands: |r2 - r1| = Delta (1e-12)", dd < 1e-12);
    test_true("strands: the pressure range of each strand is the analysis's (1e-9 relative)",
              arc == 0 && fabs(lo1 - ba->pmin1) <= 1e-9 * fabs(hi1) && fabs(hi1 - ba->pmax1) <= 1e-9 * fabs(hi1) &&
                  fabs(lo2 - ba->pmin2) <= 1e-9 * fabs(hi2) && fabs(hi2 - ba->pmax2) <= 1e-9 * fabs(hi2));
    free(ba);
    cable_strands_free(&cs);
    test_int("strands: NULL solution", cable_solution_strands(NULL, &cs), CABLE_ERR_NULL);
    /* a file's format follows its name: a PNG is never written into an .svg
     * (the CLI's o=x.svg did that silently), nor an export under another
     * suffix; refused before anything is written */
    static const struct {
      const char *png, *vtp, *ply, *key;
    } bad[] = {{"tests/tmp/pictures/k.svg", NULL, NULL, "o"},
               {"tests/tmp/pictures/k2.png", "tests/tmp/pictures/k2.vtk", NULL, "vtp"},
               {"tests/tmp/pictures/k3.png", NULL, "tests/tmp/pictures/k3.obj", "ply"}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
      cable_error_clear(&err);
      char what[160];
      snprintf(what, sizeof what, "render refuses %s: CABLE_ERR_INPUT naming the file and %s=",
               bad[i].vtp ? bad[i].vtp : bad[i].ply ? bad[i].ply : bad[i].png, bad[i].key);
      int rc = cable_render_solution(cable_cont_solution(cc), &o, bad[i].png, bad[i].vtp, bad[i].ply, &err);
      test_true(what, rc == CABLE_ERR_INPUT && strcmp(err.key, bad[i].key) == 0 && strstr(err.file, "tests/tmp/pictures/k"));
      test_true("  and writes nothing", file_size(bad[i].png) < 0 && (!bad[i].vtp || file_size(bad[i].vtp) < 0) &&
                                           (!bad[i].ply || file_size(bad[i].ply) < 0));
    }
  }
  cable_cont_free(cc);
  /* not a braid solution */
  cable_sfile *sf = cable_sfile_read("tests/tmp/pictures/s.bratu", &err);
  const cable_solution *b1 = sf ? cable_sfile_get(sf, 0) : NULL;
  cable_error_clear(&err);
  test_int("render a non-braid solution: CABLE_ERR_INPUT",
           b1 ? cable_render_solution(b1, NULL, "tests/tmp/pictures/z.png", NULL, NULL, &err) : -99, CABLE_ERR_INPUT);
  test_true("non-braid: nothing written", file_size("tests/tmp/pictures/z.png") < 0);
  cable_strands cs2;
  test_int("strands of a non-braid solution: CABLE_ERR_INPUT", b1 ? cable_solution_strands(b1, &cs2) : -99,
           CABLE_ERR_INPUT);
  test_true("  and no arrays", cs2.r1 == NULL && cs2.n == 0);
  cable_sfile_free(sf);
  graphics_text_cleanup();
  return test_summary();
}
