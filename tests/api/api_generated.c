/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The generated misuse test (doc/api.md, Contracts): every function declared
 * CABLE_API in the headers of include/cable/ is called once per pointer argument with
 * that argument NULL and the others valid (the fixtures below); the cases
 * are written by scripts/gen_api_misuse.py into BUILD/gen/api_misuse_gen.inc
 * at build time.  The test fails when a function of the headers, or one that
 * libcable.so exports, has no case.  Runs under ASan/UBSan (make asan) and
 * valgrind.  Public headers only, linked with libcable.so. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "api_check.h"
#include "cable/cable.h"

#define FX_DIR "tests/tmp/api_gen"

/* Valid objects for the arguments that are not NULL in a case. */
/* A problem resolver for cable_constants_parse_file_resolve: no problem. */
static int fx_resolve(void *ctx, const char *name, const cable_problem **pb, cable_error *err)
{
  (void)ctx;
  (void)name;
  (void)err;
  *pb = NULL;
  return 0;
}

typedef struct fx {
  cable_error err;
  cable_constants c;
  cable_names names;
  const cable_problem *pb, *pb_out;
  FILE *devnull;
  cable_session_options sopt;
  cable_session *session;        /* a fresh session: no runner state */
  cable_run_args args;           /* no arguments at all */
  cable_branch *branch;          /* Bratu through its fold, NTST 10 */
  cable_branch *branches[1];
  cable_branch *branch_out;      /* outputs, released after each case */
  cable_branch **list_out;
  cable_solution *sol;           /* the branch's LP */
  cable_sfile *sf;
  cable_bfile *bf;
  cable_cont *cc;                /* allocated, not started */
  cable_cont *cc_out;            /* cable_cont_create's output, freed after each case */
  cable_session *session_out;    /* cable_session_create's output, freed after each case */
  cable_solution *sol_out;       /* cable_solution_create's, cable_fold_create's, cable_bpcont_create's */
  cable_fold *fold_out;
  cable_bpcont *bpc_out;
  cable_constants cc_c;          /* its constants: the handle keeps them by pointer */
  cable_fold *fold;              /* the fold problem at the LP */
  cable_sink sink;               /* no callbacks */
  cable_aufile_options aopt;
  cable_braid_analysis ba;
  const cable_braid_analysis *bas[1];
  cable_tube_distance_result tube;
  cable_axis_passages ap;
  cable_strands strands;          /* cable_solution_strands' output */
  cable_stab_result stab;
  cable_plot_annotation marks[1];
  cable_render_options ropt;
  char buf[2048];
  int i;
  double d[1024];
  const char *strs[1], *bfiles[1], *sptr;
  const cable_constants *cptr;
  const cable_names *nptr;
} fx;

static const char *const bratu_over[] = {"IPS=4", "ICP=['lambda']", "NTST=10", "NCOL=3", "DS=0.1", "DSMAX=0.5",
                                         "NMX=40", "RL1=10", "ILP=1", "ISP=0"};
static const char *const bratu_text = "e = 'bratu', IPS = 4, ICP = ['lambda'], NTST = 10, NCOL = 3, DS = 0.1, NMX = 5\n";

static void fx_constants(fx *f)
{
  cable_constants_parse_string_for("c.gen", bratu_text, f->pb, &f->c, &f->names, NULL);
}

/* Every case starts from the same valid state. */
static void fx_reset(fx *f)
{
  cable_error_clear(&f->err);
  fx_constants(f);
  f->pb_out = NULL;
  f->i = 0;
  memset(f->d, 0, sizeof f->d);
  memset(f->buf, 0, sizeof f->buf);
  f->sptr = NULL;
  f->cptr = NULL;
  f->nptr = NULL;
  memset(&f->args, 0, sizeof f->args);
  memset(&f->sink, 0, sizeof f->sink);
  cable_aufile_options_init(&f->aopt);
  memset(&f->ropt, 0, sizeof f->ropt);
}

/* Whatever a case's call handed out. */
static void fx_after(fx *f)
{
  cable_branch_decref(f->branch_out);
  f->branch_out = NULL;
  cable_branch_list_free(f->list_out, f->i);
  f->list_out = NULL;
  if (f->pb_out && f->pb_out != f->pb) cable_problem_release(f->pb, f->pb_out);
  f->pb_out = NULL;
  cable_strands_free(&f->strands);
  cable_cont_free(f->cc_out);
  f->cc_out = NULL;
  cable_session_free(f->session_out);
  f->session_out = NULL;
  cable_solution_free(f->sol_out);
  f->sol_out = NULL;
  cable_fold_free(f->fold_out);
  f->fold_out = NULL;
  cable_bpcont_free(f->bpc_out);
  f->bpc_out = NULL;
}

/* A fresh writer for the functions that take one (discarded after the case). */
static cable_aufile *fx_writer(fx *f)
{
  cable_names n;
  cable_names_init(&n);
  cable_constants c;
  cable_constants_parse_string_for("c.gen", bratu_text, f->pb, &c, NULL, NULL);
  cable_constants_take_problem_dims(&c, f->pb->ndim, f->pb->nbc, f->pb->nint);
  return cable_aufile_open(FX_DIR, "genw", &c, &n, NULL, NULL);
}

/* CABLE_ERR_NULL, with a message in the error when one was passed. */
static void api_expect_null_status(fx *f, const char *what, int rc, int has_err)
{
  char line[600];
  snprintf(line, sizeof line, "%s: CABLE_ERR_NULL%s", what, has_err ? " with a message" : "");
  int ok = rc == CABLE_ERR_NULL && (!has_err || (f->err.status == rc && f->err.msg[0]));
  if (!ok) printf("  got %d (%s), error status %d, message '%s'\n", rc, cable_status_name(rc), f->err.status, f->err.msg);
  api_check(line, ok);
}

static int fx_setup(fx *f)
{
  mkdir("tests", 0755);
  mkdir("tests/tmp", 0755);
  mkdir(FX_DIR, 0755);
  memset(f, 0, sizeof *f);
  f->pb = cable_problem_builtin("bratu");
  fx_constants(f);
  f->devnull = fopen("/dev/null", "w");
  cable_session_options_init(&f->sopt);
  f->sopt.dir = FX_DIR;
  f->sopt.log = f->devnull;
  f->session = cable_session_alloc(&f->sopt);
  /* the branch, the files b./s./d.gen and c.gen from another session */
  cable_session *s = cable_session_alloc(&f->sopt);
  cable_run_args a;
  memset(&a, 0, sizeof a);
  a.e = "bratu";
  a.sv = "gen";
  a.over = bratu_over;
  a.nover = (int)(sizeof bratu_over / sizeof bratu_over[0]);
  cable_error err;
  int rc = cable_session_run(s, &a, &f->branch, &err);
  cable_session_free(s);
  char buf[1200];
  if (rc) printf("  fixture run: %s\n", cable_error_format(&err, buf, sizeof buf));
  FILE *cf = fopen(FX_DIR "/c.gen", "w");
  if (cf) {
    fputs(bratu_text, cf);
    fclose(cf);
  }
  f->branches[0] = f->branch;
  for (int i = 0; f->branch && i < cable_branch_nsolutions(f->branch); i++) {
    const cable_solution *s1 = cable_branch_solution(f->branch, i);
    if (cable_type_base(s1->itp) == 5 && !f->sol) f->sol = cable_solution_clone(s1);
  }
  f->sf = cable_sfile_read(FX_DIR "/s.gen", NULL);
  f->bf = cable_bfile_read(FX_DIR "/b.gen", NULL);
  int st = 0;
  f->cc_c = f->c;
  cable_constants_take_problem_dims(&f->cc_c, f->pb->ndim, f->pb->nbc, f->pb->nint);
  f->cc = cable_cont_alloc(f->pb, &f->cc_c, &st);
  cable_constants fc = f->cc_c;
  fc.isw = 2;
  fc.icp[1] = 1;
  fc.nicp = 2;
  char msg[300] = "";
  f->fold = cable_fold_alloc(f->pb, &fc, f->sol, &st, msg, sizeof msg);
  if (!f->fold) printf("  fixture fold: %s\n", msg);
  f->bas[0] = &f->ba;
  f->marks[0].text = "a";
  f->strs[0] = "lambda";
  f->bfiles[0] = "b.gen";
  int ok = f->session && f->branch && f->sol && f->sf && f->bf && f->bf->nbranch > 0 && f->cc && f->fold;
  api_check("the fixtures: a session, a Bratu branch with its LP, its files, a handle, a fold", ok);
  return ok;
}

static void fx_free(fx *f)
{
  cable_fold_free(f->fold);
  cable_cont_free(f->cc);
  cable_bfile_free(f->bf);
  cable_sfile_free(f->sf);
  cable_solution_free(f->sol);
  cable_branch_decref(f->branch);
  cable_session_free(f->session);
  if (f->devnull) fclose(f->devnull);
}

#include "api_misuse_gen.inc"

static int listed(const char *name)
{
  for (size_t i = 0; i < sizeof gen_covered / sizeof gen_covered[0]; i++)
    if (strcmp(gen_covered[i], name) == 0) return 1;
  return 0;
}

/* Every function of the headers and every function libcable.so exports has
 * its cases: a new entry point cannot be left out. */
static void check_coverage(void)
{
  int nh = (int)(sizeof gen_header_functions / sizeof gen_header_functions[0]), missing = 0;
  for (int i = 0; i < nh; i++)
    if (!listed(gen_header_functions[i].name)) {
      printf("  no misuse cases for %s\n", gen_header_functions[i].name);
      missing++;
    }
  char what[200];
  snprintf(what, sizeof what, "every CABLE_API function of the headers (%d) is in the misuse test", nh);
  api_check(what, missing == 0 && nh > 0);
  api_check("the exported functions of libcable.so are known (nm -D at generation)", gen_exported_known);
  int ne = 0;
  missing = 0;
  for (int i = 0; gen_exported[i]; i++, ne++) {
    int in_headers = 0;
    for (int k = 0; k < nh; k++) in_headers |= strcmp(gen_header_functions[k].name, gen_exported[i]) == 0;
    if (!in_headers || !listed(gen_exported[i])) {
      printf("  libcable.so exports %s, which the misuse test does not call\n", gen_exported[i]);
      missing++;
    }
  }
  snprintf(what, sizeof what, "every function libcable.so exports (%d) is declared and in the misuse test", ne);
  api_check(what, missing == 0 && ne >= nh);
}

/* CABLE_API_ISOLATE=1 (for finding crashes): each case in a child process,
 * a crash reported as a FAIL line instead of ending the test. */
static void run_case(fx *f, int k, int isolate)
{
  if (!isolate) {
    gen_case_fn[k](f);
    return;
  }
  fflush(stdout);
  pid_t pid = fork();
  if (pid == 0) {
    gen_case_fn[k](f);
    fflush(stdout);
    _exit(0);
  }
  int ws = 0;
  waitpid(pid, &ws, 0);
  if (!WIFEXITED(ws) || WEXITSTATUS(ws) != 0) {
    char what[400];
    snprintf(what, sizeof what, "%s: crashed (%s %d)", gen_case_name[k], WIFSIGNALED(ws) ? "signal" : "exit",
             WIFSIGNALED(ws) ? WTERMSIG(ws) : WEXITSTATUS(ws));
    api_check(what, 0);
  }
}

int main(void)
{
  check_coverage();
  fx f;
  const char *iso = getenv("CABLE_API_ISOLATE");
  int ncase = (int)(sizeof gen_case_fn / sizeof gen_case_fn[0]);
  if (fx_setup(&f))
    for (int k = 0; k < ncase; k++) run_case(&f, k, iso && iso[0] == '1');
  fx_free(&f);
  /* the two functions with process-wide effects, once, last */
  cable_blas_single_thread();
  api_check("cable_blas_single_thread (no arguments) returns", 1);
  cable_pictures_cleanup();
  api_check("cable_pictures_cleanup (no arguments) returns", 1);
  return api_summary();
}
