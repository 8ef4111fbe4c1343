/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Constants files (c.NAME) and KEY=VALUE overrides: a file with every key
 * parses to the expected values; malformed inputs each give one message
 * naming file, line and key with the expected status; overrides merge and
 * leave the constants unchanged when they fail. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cable/cable_constants.h"
#include "cable/cable_error.h"
#include "cable/cable_status.h"
#include "cable/cable_constants.h"
#include "harness.h"
#include "cable/cable_names.h"
#include "cable/cable_cont.h"
#include "test_problems.h"

#define CASEDIR "tests/tmp/constants"

/* The problem's own names (0-based), as a cable_problem would give them. */
static const char *const problem_parnames[20] = {"T", "L", "L2", NULL, NULL, NULL, NULL, NULL, NULL, NULL,
                                                 NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, "myp"};

static void test_every_key(void)
{
  cable_constants c;
  cable_names n;
  memset(&c, 0, sizeof c);   /* memcmp below compares padding too */
  cable_error e;
  char msg[1024];
  int st = cable_constants_parse_file("tests/data/c.every", &c, &n, problem_parnames, 20, &e);
  test_int("c.every parses", st, 0);
  if (st) {
    printf("  %s\n", cable_error_format(&e, msg, sizeof msg));
    return;
  }
  test_true("e, s, dat, sv", strcmp(c.e, "braid_knot") == 0 && strcmp(c.s, "flat") == 0 && strcmp(c.dat, "data") == 0 &&
                                 strcmp(c.sv, "out") == 0);
  test_true("unames {1: 'F1', 2: 'F2', 3: 'F3'}", strcmp(n.u[0], "F1") == 0 && strcmp(n.u[2], "F3") == 0 && n.u[3][0] == 0);
  test_true("parnames (line continued inside the dict)", strcmp(n.par[0], "T") == 0 && strcmp(n.par[13], "eps21") == 0 &&
                                                             strcmp(n.par[35], "err") == 0 && n.par[3][0] == 0);
  test_int("NDIM", c.ndim, 21);
  test_int("IPS", c.ips, 4);
  test_true("IRS = 'BP1': name kept, number 1 until looked up", strcmp(c.irs_name, "BP1") == 0 && c.irs == 1);
  test_int("ILP", c.ilp, 1);
  test_int("ICP: 5 parameters", c.nicp, 5);
  test_true("ICP = ['T', 'L', 3, 'eps21', 'myp'] -> 0-based 0 1 2 13 19",
            c.icp[0] == 0 && c.icp[1] == 1 && c.icp[2] == 2 && c.icp[3] == 13 && c.icp[4] == 19);
  test_int("NTST", c.ntst, 60);
  test_int("NCOL", c.ncol, 5);
  test_int("IAD", c.iad, 2);
  test_int("ISP", c.isp, 3);
  test_int("ISW", c.isw, -1);
  test_int("IPLT", c.iplt, 2);
  test_int("NBC", c.nbc, 16);
  test_int("NINT", c.nint, 2);
  test_int("NMX", c.nmx, 400);
  test_int("NPR", c.npr, 25);
  test_abs("RL0", c.rl0, -5.5, 0);
  test_abs("RL1", c.rl1, 10.0, 0);
  test_abs("A0", c.a0, 0.0, 0);
  test_abs("A1", c.a1, 1000.0, 0);
  test_abs("DS", c.ds, -0.01, 0);
  test_abs("DSMIN = 1.0d-5 (Fortran exponent)", c.dsmin, 1e-5, 0);
  test_abs("DSMAX", c.dsmax, 0.05, 0);
  test_int("IADS", c.iads, 2);
  test_abs("EPSL", c.epsl, 1e-8, 0);
  test_abs("EPSU", c.epsu, 1e-8, 0);
  test_abs("EPSS = 1.0D-6", c.epss, 1e-6, 0);
  test_int("ITMX", c.itmx, 12);
  test_int("ITNW", c.itnw, 7);
  test_int("NWTN", c.nwtn, 4);
  test_int("JAC", c.jac, 1);
  test_true("THL = {'T': 1.0, 11: 0.0}", c.nthl == 2 && c.thl[0].index == 0 && c.thl[0].weight == 1.0 &&
                                              c.thl[1].index == 10 && c.thl[1].weight == 0.0);
  test_abs("THU = {} keeps weight 1", c.thu_default, 1.0, 0);
  test_int("UZR + UZSTOP: 5 user zeros", c.nuzr, 5);
  test_true("UZR 'T': -2.10752, -1.5 (no stop)", c.uzr[0].par == 0 && c.uzr[0].value == -2.10752 && !c.uzr[0].stop &&
                                                     c.uzr[1].par == 0 && c.uzr[1].value == -1.5 && !c.uzr[1].stop);
  test_true("UZR 2: 4.0", c.uzr[2].par == 1 && c.uzr[2].value == 4.0 && !c.uzr[2].stop);
  test_true("UZR -3: 0.25 (AUTO's negative index: stop)", c.uzr[3].par == 2 && c.uzr[3].value == 0.25 && c.uzr[3].stop);
  test_true("UZSTOP \"L\": 12.0", c.uzr[4].par == 1 && c.uzr[4].value == 12.0 && c.uzr[4].stop);
  test_true("STOP = ['BP2', 'UZ3']", c.nstop == 2 && c.stop_on[0] == 6 && c.stop_count[0] == 2 && c.stop_on[1] == -4 &&
                                         c.stop_count[1] == 3);
  test_int("IID", c.iid, 3);
  test_int("IIS", c.iis, 2);
  test_int("NPAR", c.npar, 36);
  test_true("LINSOLVER = 'klu'", c.linsolver == CABLE_LINSOLVER_KLU);
  test_int("NSV", c.nsv, 3);
  test_int("BPDIR", c.bpsym, 1);
  test_int("PREDICTOR", c.predictor, 2);

  /* defaults of keys a file leaves out */
  cable_constants d, ref;
  cable_constants_init(&ref);
  st = cable_constants_parse_string("c.small", "NTST = 7\n", &d, NULL, NULL, 0, &e);
  test_int("a one-key file parses (names NULL, no problem names)", st, 0);
  test_true("  other keys keep AUTO's defaults (DS 0.01, NCOL 4, EPSL 1e-7, NMX 0, ICP empty)",
            d.ds == ref.ds && d.ncol == 4 && d.epsl == 1e-7 && d.nmx == ref.nmx && d.nicp == 0 && d.ntst == 7);
  test_int("  PREDICTOR defaults to 1 (AUTO's tangent predictor)", d.predictor, 1);

  /* overrides on top of the file */
  cable_constants before = c;
  st = cable_constants_parse_override("DS=-0.05", &c, &n, problem_parnames, 20, &e);
  test_true("override DS=-0.05", st == 0 && c.ds == -0.05);
  st = cable_constants_parse_override("DS='-'", &c, &n, problem_parnames, 20, &e);
  test_true("override DS='-' reverses the direction", st == 0 && c.ds == 0.05);
  c.ntst = before.ntst;
  st = cable_constants_parse_override("ICP=['eps21', 'T']", &c, &n, problem_parnames, 20, &e);
  test_true("override ICP by the file's names", st == 0 && c.nicp == 2 && c.icp[0] == 13 && c.icp[1] == 0);
  st = cable_constants_parse_override("UZR={'L': [1.0, 2.0]}", &c, &n, problem_parnames, 20, &e);
  int stops = 0, plain = 0;
  for (int k = 0; k < c.nuzr; k++) stops += c.uzr[k].stop, plain += !c.uzr[k].stop;
  test_true("override UZR replaces the user zeros, keeps the two stopping ones", st == 0 && plain == 2 && stops == 2);
  st = cable_constants_parse_override("UZSTOP={}", &c, &n, problem_parnames, 20, &e);
  stops = 0;
  for (int k = 0; k < c.nuzr; k++) stops += c.uzr[k].stop;
  test_true("override UZSTOP={} removes the stopping zeros", st == 0 && stops == 0 && c.nuzr == 2);
  st = cable_constants_parse_override("IRS=-3, NMX=50", &c, &n, problem_parnames, 20, &e);
  test_true("override with two statements: IRS=-3 (third solution), NMX=50",
            st == 0 && c.irs == -3 && c.irs_name[0] == 0 && c.nmx == 50);
  st = cable_constants_parse_override("parnames={1: 'A', 2: 'B'}", &c, &n, problem_parnames, 20, &e);
  test_true("override parnames", st == 0 && strcmp(n.par[0], "A") == 0 && n.par[13][0] == 0);
  st = cable_constants_parse_override("ICP=['A', 'myp']", &c, &n, problem_parnames, 20, &e);
  test_true("  new names and the problem's names both resolve", st == 0 && c.icp[0] == 0 && c.icp[1] == 19);
  st = cable_constants_parse_override("LINSOLVER=condense", &c, &n, problem_parnames, 20, &e);
  test_true("override with a bare word: LINSOLVER=condense", st == 0 && c.linsolver == CABLE_LINSOLVER_CONDENSE);

  cable_constants keep;
  cable_names keepn;
  memcpy(&keep, &c, sizeof c);
  memcpy(&keepn, &n, sizeof n);
  st = cable_constants_parse_override("NTST=-5", &c, &n, problem_parnames, 20, &e);
  cable_error_format(&e, msg, sizeof msg);
  printf("  message: %s\n", msg);
  test_true("failing override NTST=-5: status, key and the override in the message",
            st == CABLE_ERR_INPUT && strcmp(e.key, "NTST") == 0 && strstr(msg, "NTST: ") && strstr(msg, "'NTST=-5'"));
  test_true("  constants and names unchanged", memcmp(&keep, &c, sizeof c) == 0 && memcmp(&keepn, &n, sizeof n) == 0);
  st = cable_constants_parse_override("ICP=['T', 'nope']", &c, &n, problem_parnames, 20, &e);
  test_true("failing override ICP=['T', 'nope']: not found, unchanged",
            st == CABLE_ERR_NOTFOUND && memcmp(&keep, &c, sizeof c) == 0);
  st = cable_constants_parse_override("IBR=2", &c, &n, problem_parnames, 20, &e);
  test_true("override of an unsupported AUTO key (IBR)", st == CABLE_ERR_UNSUPPORTED);
  {
    cable_constants c2 = c;
    cable_names n2 = n;
    st = cable_constants_parse_override("MXBF=2", &c2, &n2, problem_parnames, 20, &e);
    test_true("override MXBF=2: AUTO ignores it for BVPs, accepted and listed as ignored",
              st == 0 && strstr(c2.ignored, "MXBF") != NULL);
  }
  st = cable_constants_parse_override("", &c, &n, problem_parnames, 20, &e);
  test_true("empty override is an error", st == CABLE_ERR_PARSE);
  st = cable_constants_parse_override("NTST=5, NTST=6", &c, &n, problem_parnames, 20, &e);
  test_true("duplicate key inside one override", st == CABLE_ERR_INPUT && strstr(e.msg, "duplicate"));
  st = cable_constants_parse_override("NPAR=4", &c, &n, problem_parnames, 20, &e);
  test_true("NPAR=4 with ICP naming PAR(20): refused, unchanged",
            st == CABLE_ERR_INPUT && strcmp(e.key, "ICP") == 0 && memcmp(&keep, &c, sizeof c) == 0);
  st = cable_constants_parse_file("tests/data/c.every", &c, &n, NULL, 0, &e);
  test_true("c.every without the problem's names: 'myp' unknown, line 7, ICP",
            st == CABLE_ERR_NOTFOUND && e.line == 7 && strcmp(e.key, "ICP") == 0 && memcmp(&keep, &c, sizeof c) == 0);
}

typedef struct {
  const char *name;     /* file name under CASEDIR */
  const char *text;
  int status;
  int line;
  const char *key;
  const char *needle;   /* must appear in the message */
} bad_case;

static const bad_case bad_cases[] = {
  {"c.missing_eq", "NDIM = 3\nNTST 20\n", CABLE_ERR_PARSE, 2, "NTST", "missing '='"},
  {"c.unknown_key", "NDIM=3\nFOO = 1\n", CABLE_ERR_INPUT, 2, "FOO", "unknown key"},
  {"c.wrong_case", "ntst = 5\n", CABLE_ERR_INPUT, 1, "ntst", "did you mean 'NTST'"},
  {"c.wrong_type", "NDIM = 2\nNTST = 'abc'\n", CABLE_ERR_INPUT, 2, "NTST", "must be an integer"},
  {"c.real_for_int", "NTST = 20.0\n", CABLE_ERR_INPUT, 1, "NTST", "must be an integer, got '20.0'"},
  {"c.nan", "NDIM=3, DS = nan\n", CABLE_ERR_NONFINITE, 1, "DS", "finite"},
  {"c.inf", "\n\nRL1 = 1e999\n", CABLE_ERR_NONFINITE, 3, "RL1", "finite"},
  {"c.neg_inf", "A0 = -inf\n", CABLE_ERR_NONFINITE, 1, "A0", "'-inf'"},
  {"c.nan_in_list", "UZR = {'T': [1.0,\n     nan]}\n", CABLE_ERR_NONFINITE, 2, "UZR", "finite"},
  {"c.ntst_negative", "# comment\nNTST = -5\n", CABLE_ERR_INPUT, 2, "NTST", ">= 1, got -5"},
  {"c.ncol_9", "NCOL=9\n", CABLE_ERR_INPUT, 1, "NCOL", "2..7"},
  {"c.unknown_par", "parnames = {1: 'T'}\nICP = ['T', 'Q']\n", CABLE_ERR_NOTFOUND, 2, "ICP", "unknown parameter name 'Q'"},
  {"c.unknown_uzr_par", "UZR = {'Zeta': 1.0}\n", CABLE_ERR_NOTFOUND, 1, "UZR", "'Zeta'"},
  {"c.unknown_label", "IRS = 'XY1'\n", CABLE_ERR_INPUT, 1, "IRS", "unknown label 'XY1'"},
  {"c.label_no_number", "IRS = 'BP'\n", CABLE_ERR_INPUT, 1, "IRS", "unknown label 'BP'"},
  {"c.stop_hb", "STOP = ['HB1']\n", CABLE_ERR_INPUT, 1, "STOP", "unknown label"},
  {"c.unterminated_list", "ICP = [1, 2\nNTST = 5\n", CABLE_ERR_PARSE, 1, "ICP", "unterminated list"},
  {"c.unterminated_list_eof", "NTST = 5\nICP = [1,\n  2", CABLE_ERR_PARSE, 2, "ICP", "unterminated list"},
  {"c.unterminated_dict", "UZR = {'T': [1.0, 2.0}\n", CABLE_ERR_PARSE, 1, "UZR", "expected ',' or ']'"},
  {"c.unterminated_string", "e = 'braid_knot\nNTST=5\n", CABLE_ERR_PARSE, 1, "e", "unterminated string"},
  {"c.duplicate", "NTST=5\nNCOL=4\nNTST=6\n", CABLE_ERR_INPUT, 3, "NTST", "duplicate key (first set on line 1)"},
  {"c.ibr", "NDIM=2, IBR = 10\n", CABLE_ERR_UNSUPPORTED, 1, "IBR", "not supported by cable"},
  {"c.sp", "SP = ['LP0']\n", CABLE_ERR_UNSUPPORTED, 1, "SP", "not supported by cable"},
  {"c.tykey", "TY = 'BP'\n", CABLE_ERR_UNSUPPORTED, 1, "TY", "not supported by cable"},
  {"c.ips2", "IPS = 2\n", CABLE_ERR_UNSUPPORTED, 1, "IPS", "IPS=4 boundary-value problems only"},
  {"c.isw3", "ISW = 3\n", CABLE_ERR_UNSUPPORTED, 1, "ISW", "not supported"},
  {"c.iplt_range", "NDIM = 2\nIPLT = -3\n", CABLE_ERR_INPUT, 2, "IPLT", "outside -NDIM..3*NDIM"},
  {"c.rl_order", "RL0 = 5\nRL1 = 1\n", CABLE_ERR_INPUT, 2, "RL1", "less than RL1"},
  {"c.ds_order", "DSMIN = 0.5, DSMAX = 0.1\n", CABLE_ERR_INPUT, 1, "DSMAX", "must not exceed"},
  {"c.ds_zero", "DS = 0\n", CABLE_ERR_INPUT, 1, "DS", "non-zero"},
  {"c.icp_beyond_npar", "NPAR = 10\nICP = [1, 12]\n", CABLE_ERR_INPUT, 2, "ICP", "beyond NPAR=10"},
  {"c.icp_twice", "ICP = [1, 'T', 1]\n", CABLE_ERR_INPUT, 1, "ICP", "listed twice"},
  {"c.bad_number", "DS = 1.0.0\n", CABLE_ERR_PARSE, 1, "DS", "bad number"},
  {"c.uzr_list", "UZR = [1, 2]\n", CABLE_ERR_INPUT, 1, "UZR", "must be a dict"},
  {"c.trailing", "NTST = 5 6\n", CABLE_ERR_PARSE, 1, "NTST", "unexpected '6'"},
  {"c.missing_value", "NTST =\nNCOL = 4\n", CABLE_ERR_PARSE, 1, "NTST", "missing value"},
  {"c.thu", "NDIM = 2\nTHU = {1: 2.0}\n", CABLE_ERR_UNSUPPORTED, 2, "THU", "non-uniform THU"},
  {"c.thu_name", "THU = {'Z': 1.0}\n", CABLE_ERR_NOTFOUND, 1, "THU", "unknown component name 'Z'"},
  {"c.old_style", "2 4 0 1\n1 1\n", CABLE_ERR_UNSUPPORTED, 1, "", "old-style"},
  {"c.parnames_twice", "parnames = {1: 'T', 2: 'T'}\n", CABLE_ERR_INPUT, 1, "parnames", "given to indices 1 and 2"},
  {"c.parnames_number", "parnames = {1: '12'}\n", CABLE_ERR_INPUT, 1, "parnames", "is a number"},
  {"c.linsolver", "LINSOLVER = 'lu'\n", CABLE_ERR_INPUT, 1, "LINSOLVER", "'condense' or 'klu'"},
  {"c.int_range", "NMX = 99999999999\n", CABLE_ERR_INPUT, 1, "NMX", "out of range"},
  {"c.tuple", "ICP = (1, 2)\n", CABLE_ERR_PARSE, 1, "ICP", "tuples"},
  {"c.bad_char", "NTST = 5 @\n", CABLE_ERR_PARSE, 1, "NTST", "unexpected character '@'"},
  {"c.iis", "IIS = 4\n", CABLE_ERR_INPUT, 1, "IIS", "0..3"},
  {"c.jac", "JAC = 2\n", CABLE_ERR_INPUT, 1, "JAC", "-1..1"},
  {"c.predictor", "NTST = 5\nPREDICTOR = 3\n", CABLE_ERR_INPUT, 2, "PREDICTOR", "1..2"},
  {"c.eps_negative", "EPSL = -1e-7\n", CABLE_ERR_INPUT, 1, "EPSL", "positive"},
  {"c.npar_big", "NPAR = 100000\n", CABLE_ERR_INPUT, 1, "NPAR", "1..256"},
  {"c.empty_icp", "ICP = []\n", CABLE_ERR_INPUT, 1, "ICP", "at least one"},
};

static void write_file(const char *path, const char *text)
{
  FILE *f = fopen(path, "w");
  if (f) {
    fputs(text, f);
    fclose(f);
  }
}

static void test_bad_cases(void)
{
  mkdir("tests/tmp", 0755);
  mkdir(CASEDIR, 0755);
  int n = (int)(sizeof bad_cases / sizeof bad_cases[0]);
  for (int i = 0; i < n; i++) {
    const bad_case *b = &bad_cases[i];
    char path[256], msg[1024], want[512], what[1200];
    snprintf(path, sizeof path, CASEDIR "/%s", b->name);
    write_file(path, b->text);
    cable_constants c;
    cable_constants_init(&c);
    c.ntst = 1234;   /* the parser must not touch c on failure */
    cable_names nm;
    cable_names_init(&nm);
    cable_error e;
    int st = cable_constants_parse_file(path, &c, &nm, problem_parnames, 20, &e);
    cable_error_format(&e, msg, sizeof msg);
    if (b->key[0]) snprintf(want, sizeof want, "%s:%d: %s: ", path, b->line, b->key);
    else snprintf(want, sizeof want, "%s:%d: ", path, b->line);
    int ok = st == b->status && e.line == b->line && strcmp(e.key, b->key) == 0 && strncmp(msg, want, strlen(want)) == 0 &&
             strstr(msg, b->needle) != NULL && strchr(msg, '\n') == NULL && c.ntst == 1234;
    snprintf(what, sizeof what, "%-24s status %d (want %d): %s", b->name, st, b->status, msg);
    test_true(what, ok);
  }
  /* a file that does not exist */
  cable_constants c;
  cable_error e;
  char msg[1024];
  int st = cable_constants_parse_file("tests/data/c.does_not_exist", &c, NULL, NULL, 0, &e);
  cable_error_format(&e, msg, sizeof msg);
  printf("  message: %s\n", msg);
  test_true("missing constants file: I/O error naming the file",
            st == CABLE_ERR_IO && strncmp(msg, "tests/data/c.does_not_exist: ", 29) == 0);
  /* a binary file */
  static const char bin[] = "NTST = 5\n\0\1\2";
  FILE *f = fopen(CASEDIR "/c.binary", "wb");
  if (f) {
    fwrite(bin, 1, sizeof bin, f);
    fclose(f);
  }
  st = cable_constants_parse_file(CASEDIR "/c.binary", &c, NULL, NULL, 0, &e);
  test_true("binary file refused", st == CABLE_ERR_PARSE && strstr(e.msg, "NUL"));
  cable_constants_init(&c);
  c.nbc = 5;
  cable_constants_take_problem_dims(&c, 21, 16, 2);
  test_true("take_problem_dims fills NDIM and NINT, keeps the file's NBC", c.ndim == 21 && c.nbc == 5 && c.nint == 2);
  test_true("cable_constants_key_known: NTST yes, MXBF no", cable_constants_key_known("NTST") &&
                                                             !cable_constants_key_known("MXBF"));
}

static void test_names(void)
{
  cable_names n;
  cable_names_init(&n);
  strcpy(n.par[4], "T");   /* file renames PAR(5) 'T'; the problem has 'T' at 0 */
  const char *const pn[3] = {"T", "L", NULL};
  const char *const un[2] = {"x", NULL};
  test_int("file names win over the problem's", cable_names_par_index(&n, "T", pn, 3), 4);
  test_int("problem's names are found", cable_names_par_index(&n, "L", pn, 3), 1);
  test_int("unknown name: -1", cable_names_par_index(&n, "Q", pn, 3), -1);
  cable_names_fill(&n, pn, 3, un, 2);
  test_true("fill skips a name already used elsewhere, adds the others",
            n.par[0][0] == 0 && strcmp(n.par[1], "L") == 0 && strcmp(n.u[0], "x") == 0);
  int type = 0, nth = 0;
  test_true("label spec 'UZ12'", cable_label_spec_parse("UZ12", &type, &nth) == 0 && type == -4 && nth == 12);
  test_true("label specs 'BP0', 'B1', 'BPx', 'ZZ1' refused",
            cable_label_spec_parse("BP0", &type, &nth) && cable_label_spec_parse("B1", &type, &nth) &&
                cable_label_spec_parse("BPx", &type, &nth) && cable_label_spec_parse("ZZ1", &type, &nth));
  test_true("type names: 6 BP, -4 UZ, 26 BP (branch-type digit), 4 RG, 0 ''",
            strcmp(cable_type_name(6), "BP") == 0 && strcmp(cable_type_name(-4), "UZ") == 0 &&
                strcmp(cable_type_name(26), "BP") == 0 && strcmp(cable_type_name(4), "RG") == 0 &&
                strcmp(cable_type_name(0), "") == 0);
}

/* Problem-specific keys (ABI 2): the braid problems declare TORUS and HAND;
 * the parser checks them with file:line:key errors, keeps their values, and
 * refuses them for a problem that does not declare them. */
static void test_problem_keys(void)
{
  const cable_problem *knot = cable_problem_builtin("braid_knot");
  cable_constants c;
  cable_error err;
  char buf[1200];
  test_true("braid_knot declares keys", knot && knot->nkeys == 2);
  int rc = cable_constants_parse_string_for("c.k", "NTST = 50\nTORUS = 7, HAND = 'left'\n", knot, &c, NULL, &err);
  test_int("TORUS and HAND parse for braid_knot", rc, 0);
  test_abs("  TORUS", cable_constants_key(&c, knot, "TORUS"), 7, 0);
  test_abs("  HAND 'left' is -1", cable_constants_key(&c, knot, "HAND"), -1, 0);
  rc = cable_constants_parse_string_for("c.k", "NTST = 50\n", knot, &c, NULL, &err);
  test_abs("  HAND unset: the problem's default 1", cable_constants_key(&c, knot, "HAND"), 1, 0);
  test_abs("  TORUS unset: the default 0", cable_constants_key(&c, knot, "TORUS"), 0, 0);
  test_true("  a key the problem does not declare: NaN", isnan(cable_constants_key(&c, knot, "NOSUCH")));
  rc = cable_constants_parse_string_for("c.k", "NTST = 50\n\nTORUS = 2.5\n", knot, &c, NULL, &err);
  test_int("TORUS = 2.5: CABLE_ERR_INPUT", rc, CABLE_ERR_INPUT);
  cable_error_format(&err, buf, sizeof buf);
  test_true("  message names file, line and key", strncmp(buf, "c.k:3: TORUS: must be an integer", 32) == 0);
  rc = cable_constants_parse_string_for("c.k", "HAND = 0\n", knot, &c, NULL, &err);
  test_int("HAND = 0 (not one of the words' values): CABLE_ERR_INPUT", rc, CABLE_ERR_INPUT);
  test_true("  message", strstr(cable_error_format(&err, buf, sizeof buf), "c.k:1: HAND: 0 is not an accepted value") == buf);
  rc = cable_constants_parse_string_for("c.b", "TORUS = 7\n", cable_problem_builtin("bratu"), &c, NULL, &err);
  test_int("TORUS for bratu: unknown key", rc, CABLE_ERR_INPUT);
  test_true("  message", strcmp(cable_error_format(&err, buf, sizeof buf), "c.b:1: TORUS: unknown key") == 0);
  rc = cable_constants_parse_string("c.n", "TORUS = 7\n", &c, NULL, NULL, 0, &err);
  test_int("TORUS without a problem: unknown key", rc, CABLE_ERR_INPUT);
  cable_constants_parse_string_for("c.k", "TORUS = 5\n", knot, &c, NULL, &err);
  rc = cable_constants_parse_override_for("TORUS=9", knot, &c, NULL, &err);
  test_int("an override replaces a problem key", rc, 0);
  test_abs("  TORUS now 9", cable_constants_key(&c, knot, "TORUS"), 9, 0);
  test_int("  and is kept once", c.npkey, 1);
  test_true("cable_constants_key_known_for: TORUS for braid_knot, not for bratu",
            cable_constants_key_known_for(knot, "TORUS") &&
                !cable_constants_key_known_for(cable_problem_builtin("bratu"), "TORUS"));
}

/* AUTO's PAR: a keyword PAR={...} over a constants file's PAR updates the
 * entries it names and keeps the others (before: it replaced the whole list,
 * so PAR={'L': 0.5} over a file's {'T': 1.5, 'L2': 2.5, 5: 3.5} lost T, L2
 * and PAR(5)). */
static void test_par_update(void)
{
  cable_constants c;
  cable_names n;
  cable_error e;
  cable_constants_init(&c);
  int st = cable_constants_parse_string("c.par", "NDIM=2\nPAR = {'T': 1.5, 'L2': 2.5, 5: 3.5}\n", &c, &n,
                                        problem_parnames, 20, &e);
  test_true("c.par with PAR = {'T': 1.5, 'L2': 2.5, 5: 3.5} parses", st == 0 && c.npar_override == 3);
  st = cable_constants_parse_override("PAR={'L': 0.5, 'L2': -1.0}", &c, &n, problem_parnames, 20, &e);
  double want[6] = {1.5, 0.5, -1.0, NAN, 3.5, NAN};   /* by index: T, L, L2, -, PAR(5) */
  int found[6] = {0};
  for (int k = 0; k < c.npar_override; k++)
    if (c.par_override[k].index >= 0 && c.par_override[k].index < 6) {
      found[c.par_override[k].index]++;
      test_abs("PAR override: the entry's value", c.par_override[k].value, want[c.par_override[k].index], 0.0);
    }
  test_true("PAR={'L': 0.5, 'L2': -1.0} over the file's PAR: 4 entries, each once (T and PAR(5) kept, L added, "
            "L2 updated)",
            st == 0 && c.npar_override == 4 && found[0] == 1 && found[1] == 1 && found[2] == 1 && found[4] == 1);
}

/* An integer key's range is written once, in the key table: the engine's
 * check of constants filled by hand gives the parser's words for NTST, NCOL
 * and the other integer keys, and refuses what a file could not set. */
static void test_ranges_once(void)
{
  const cable_problem *pb = cable_testproblem_bratu();
  cable_constants c, f;
  cable_error err, perr_;
  struct {
    const char *file, *key, *engine;
  } cases[] = {
    {"NTST = -5", "NTST", "NTST: must be an integer >= 1, got -5"},
    {"NCOL = 9", "NCOL", "NCOL: must be an integer in 2..7, got 9"},
    {"ILP = 3", "ILP", "ILP: must be an integer in 0..1, got 3"},
    {"NPR = -1", "NPR", "NPR: must be an integer >= 0, got -1"},
  };
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
    int pst = cable_constants_parse_string("c.r", cases[k].file, &f, NULL, NULL, 0, &perr_);
    cable_constants_init(&c);
    c.ips = 4;
    c.icp[0] = 0;
    c.nicp = 1;
    int value = 0;
    sscanf(strchr(cases[k].file, '=') + 1, "%d", &value);
    if (strcmp(cases[k].key, "NTST") == 0) c.ntst = value;
    if (strcmp(cases[k].key, "NCOL") == 0) c.ncol = value;
    if (strcmp(cases[k].key, "ILP") == 0) c.ilp = value;
    if (strcmp(cases[k].key, "NPR") == 0) c.npr = value;
    int est = cable_cont_check(pb, &c, &err);
    /* the file's error: key NTST, message "must be ..."; the engine's: "NTST: must be ..." */
    test_true(cases[k].engine, pst == CABLE_ERR_INPUT && est == CABLE_ERR_INPUT &&
                                   strcmp(err.msg, cases[k].engine) == 0 && strcmp(perr_.key, cases[k].key) == 0 &&
                                   strcmp(perr_.msg, strchr(cases[k].engine, ':') + 2) == 0);
  }
  cable_constants_init(&c);
  c.ips = 4;
  c.icp[0] = 0;
  c.nicp = 1;
  test_true("defaults pass the engine's ranges (NDIM, NBC, NINT 0: the problem's)",
            cable_cont_check(pb, &c, &err) == 0);
}

int main(void)
{
  test_ranges_once();
  test_par_update();
  test_every_key();
  test_bad_cases();
  test_names();
  test_problem_keys();
  return test_summary();
}
