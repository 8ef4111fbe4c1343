/* SPDX-License-Identifier: GPL-3.0-or-later */
/* AUTO's routines behind cable's problem interface: the Fortran calling
 * convention (everything by reference) or AUTO's C interface, 1-based ICP as
 * AUTO passes it, the derivative arrays AUTO always passes, dat= start data,
 * and GETP for PVLS. */
#include <ctype.h>
#include <dlfcn.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "autoeq_impl.h"
#include "cable/cable_solution.h"
#include "cable/cable_status.h"
#include "colloc_basis.h"

/* ICP as AUTO passes it: 1-based, the free parameters the engine uses first,
 * then the rest of the run's ICP list. */
static const int *icp_for_auto(cable_autoeq *m, const int *icp)
{
  int k = 0;
  for (; k < m->nfpr0 && icp; k++) m->icp1[k] = icp[k] + 1;
  for (; k < m->nicp; k++) m->icp1[k] = m->icp_tail[k];
  for (; k < AUTOEQ_MAX_ICP; k++) m->icp1[k] = 0;
  return m->icp1;
}

/* Scratch for derivative arrays the engine does not ask for (AUTO always
 * passes them; a routine may write them whatever IJAC says). */
static double *scratch(cable_autoeq *m, int which)
{
  size_t nd = (size_t)m->ndim, np = (size_t)m->npar, nb = (size_t)m->nbc;
  size_t off[4] = {0, nd * nd, nd * nd + nd * np, nd * nd + nd * np + nb * (2 * nd + np)};
  return m->scratch + off[which];
}

static int ae_func(int ndim, const double *u, const int *icp, const double *par, int ijac, double *f, double *dfdu,
                   double *dfdp, void *params)
{
  cable_autoeq *m = params;
  const int *ic = icp_for_auto(m, icp);
  if (!dfdu) dfdu = scratch(m, 0);
  if (!dfdp) dfdp = scratch(m, 1);
  if (m->c_tab) return m->c_tab->func(ndim, u, ic, par, ijac, f, dfdu, dfdp);
  m->f_func(&ndim, u, ic, par, &ijac, f, dfdu, dfdp);
  return 0;
}

static int ae_bcnd(int ndim, const double *par, const int *icp, int nbc, const double *u0, const double *u1, int ijac,
                   double *fb, double *dbc, void *params)
{
  cable_autoeq *m = params;
  const int *ic = icp_for_auto(m, icp);
  if (!dbc) dbc = scratch(m, 2);
  if (m->c_tab) return m->c_tab->bcnd(ndim, par, ic, nbc, u0, u1, ijac, fb, dbc);
  m->f_bcnd(&ndim, par, ic, &nbc, u0, u1, fb, &ijac, dbc);
  return 0;
}

static int ae_icnd(int ndim, const double *par, const int *icp, int nint, const double *u, const double *uold,
                   const double *udot, const double *upold, int ijac, double *fi, double *dint, void *params)
{
  cable_autoeq *m = params;
  const int *ic = icp_for_auto(m, icp);
  if (!dint) dint = scratch(m, 3);
  if (m->c_tab) return m->c_tab->icnd(ndim, par, ic, nint, u, uold, udot, upold, ijac, fi, dint);
  m->f_icnd(&ndim, par, ic, &nint, u, uold, udot, upold, fi, &ijac, dint);
  return 0;
}

/* u(t) from the dat= table: linear interpolation in the rescaled t. */
static void dat_eval(const cable_autoeq *m, double t, double *u)
{
  int w = m->ndim + 1, k = 0;
  while (k + 2 < m->ndat && m->dat[(k + 1) * w] < t) k++;
  const double *a = m->dat + k * w, *b = m->ndat > 1 ? a + w : a;
  double s = b[0] > a[0] ? (t - a[0]) / (b[0] - a[0]) : 0.0;
  s = fmin(1.0, fmax(0.0, s));
  for (int i = 0; i < m->ndim; i++) u[i] = a[1 + i] + s * (b[1 + i] - a[1 + i]);
}

static int ae_stpnt(int ndim, double t, double *u, double *par, void *params)
{
  cable_autoeq *m = params;
  int rc = 0;
  if (m->c_tab) rc = m->c_tab->stpnt(ndim, t, u, par);
  else if (m->f_stpnt && m->nargs[AE_STPNT] > 0) m->f_stpnt(&ndim, u, par, &t);
  if (m->dat) dat_eval(m, t, u);
  return rc;
}

/* ---- GETP ------------------------------------------------------------------ */

static double getp_value(cable_autoeq *m, const char *code, int ic)
{
  const cable_solution *s = m->pvls_sol;
  int nd = s->ndim, npts = cable_solution_npts(s);
  if (strcasecmp(code, "STP") == 0) return s->pvls_ds;
  if (strcasecmp(code, "FLD") == 0) return s->pvls_fld;
  if (strcasecmp(code, "BIF") == 0) return s->pvls_bif;
  /* the discretisation and the problem's sizes (AUTO: NDIM, NDX, NTST, NCOL,
     NBC, NINT, read by their first three letters) */
  if (strcasecmp(code, "NDI") == 0 || strcasecmp(code, "NDX") == 0) return nd;
  if (strcasecmp(code, "NTS") == 0) return s->ntst;
  if (strcasecmp(code, "NCO") == 0) return s->ncol;
  if (strcasecmp(code, "NBC") == 0) return m->nbc;
  if (strcasecmp(code, "NIN") == 0) return m->nint;
  if (strcasecmp(code, "DTM") == 0) {   /* the length of mesh interval IC, 1..NTST */
    if (ic < 1 || ic > s->ntst) {
      snprintf(m->getp_error, sizeof m->getp_error, "GETP('DTM', %d): the interval must be 1..NTST = %d", ic,
               s->ntst);
      return nan("");
    }
    return s->t[ic * s->ncol] - s->t[(ic - 1) * s->ncol];
  }
  if (strcasecmp(code, "WIN") == 0) {   /* the node quadrature weight IC, 0..NCOL, on a unit interval */
    colloc_basis b;
    if (ic < 0 || ic > s->ncol || colloc_basis_init(&b, s->ncol) != 0) {
      snprintf(m->getp_error, sizeof m->getp_error, "GETP('WINT', %d): the node must be 0..NCOL = %d", ic, s->ncol);
      return nan("");
    }
    return b.wn[ic];
  }
  if (ic < 1 || ic > nd) {
    snprintf(m->getp_error, sizeof m->getp_error, "GETP('%s', %d): the component must be 1..NDIM = %d", code, ic, nd);
    return nan("");
  }
  int i = ic - 1;
  if (strcasecmp(code, "BV0") == 0) return s->u[i];
  if (strcasecmp(code, "BV1") == 0) return s->u[(size_t)(npts - 1) * (size_t)nd + (size_t)i];
  if (strcasecmp(code, "MAX") == 0 || strcasecmp(code, "MIN") == 0 || strcasecmp(code, "MXT") == 0 ||
      strcasecmp(code, "MNT") == 0) {
    /* MAX, MIN: the largest and smallest U(IC) over the stored points; MXT,
       MNT: the t where they are (the first such point) */
    int mx = toupper((unsigned char)code[1]) == 'A' || toupper((unsigned char)code[1]) == 'X';
    int at_t = toupper((unsigned char)code[2]) == 'T';
    double v = s->u[i];
    int kbest = 0;
    for (int k = 1; k < npts; k++) {
      double x = s->u[(size_t)k * (size_t)nd + (size_t)i];
      if (mx ? x > v : x < v) {
        v = x;
        kbest = k;
      }
    }
    return at_t ? s->t[kbest] : v;
  }
  if (strcasecmp(code, "INT") == 0 || strcasecmp(code, "NRM") == 0)
    /* the integral and the L2 norm of U(IC): IPLT's measures NDIM+IC and 2 NDIM+IC */
    return cable_solution_measure(s, (toupper((unsigned char)code[0]) == 'N' ? 2 : 1) * nd + ic, nan(""));
  snprintf(m->getp_error, sizeof m->getp_error, "GETP('%s'): not a code cable provides", code);
  return nan("");
}

static double ae_getp(const cable_getp_header *h, const char *code, size_t len, int ic)
{
  cable_autoeq *m = h->ctx;
  char c[4] = "";
  snprintf(c, sizeof c, "%.*s", (int)(len < 3 ? len : 3), code ? code : "");
  if (!m || !m->pvls_sol) return nan("");
  return getp_value(m, c, ic);
}

static int ae_pvls(const cable_solution *sol, double *par, void *params)
{
  cable_autoeq *m = params;
  if (m->nargs[AE_PVLS] <= 0) return 0;
  size_t nu = (size_t)cable_solution_npts(sol) * (size_t)sol->ndim;
  size_t need = sizeof(cable_getp_header) / sizeof(double) + nu;
  if (need > m->npvls_block) {
    double *b = realloc(m->pvls_block, need * sizeof *b);
    if (!b) return CABLE_ERR_ALLOC;
    m->pvls_block = b;
    m->npvls_block = need;
  }
  cable_getp_header *h = (cable_getp_header *)(void *)m->pvls_block;
  double *u = m->pvls_block + sizeof(cable_getp_header) / sizeof(double);
  memcpy(u, sol->u, nu * sizeof *u);
  h->magic = CABLE_GETP_MAGIC;
  h->getp = ae_getp;
  h->ctx = m;
  m->pvls_sol = sol;
  m->getp_error[0] = '\0';
  int nd = sol->ndim, rc = 0;
  if (m->c_tab) rc = m->c_tab->pvls(nd, u, par);
  else m->f_pvls(&nd, u, par);
  h->magic = 0;
  m->pvls_sol = NULL;
  return m->getp_error[0] ? CABLE_ERR_CALLBACK : rc;
}

/* ---- binding and the problem ------------------------------------------------- */

int autoeq_bind(cable_autoeq *m, cable_error *err)
{
  void *sym[AE_NROUTINES] = {NULL};
  if (m->lang == AUTOEQ_C) {
    void *t = dlsym(m->handle, "cable_auto_user");
    if (!t)
      return cable_error_set(err, CABLE_ERR_PLUGIN, m->src, 0, "", "the module has no cable_auto_user table (was "
                             "auto_f2c.h included?)");
    m->c_tab = t;
    return 0;
  }
  for (int r = 0; r < AE_NROUTINES; r++) {
    char name[16];
    size_t n = strlen(autoeq_routine_name[r]);
    for (size_t i = 0; i < n; i++) name[i] = (char)tolower((unsigned char)autoeq_routine_name[r][i]);
    name[n] = '_';
    name[n + 1] = '\0';
    sym[r] = m->nargs[r] >= 0 ? dlsym(m->handle, name) : NULL;
  }
  /* POSIX: dlsym's result has the function's representation */
  memcpy(&m->f_func, &sym[AE_FUNC], sizeof m->f_func);
  memcpy(&m->f_stpnt, &sym[AE_STPNT], sizeof m->f_stpnt);
  memcpy(&m->f_bcnd, &sym[AE_BCND], sizeof m->f_bcnd);
  memcpy(&m->f_icnd, &sym[AE_ICND], sizeof m->f_icnd);
  memcpy(&m->f_pvls, &sym[AE_PVLS], sizeof m->f_pvls);
  if (!m->f_func) return cable_error_set(err, CABLE_ERR_PLUGIN, m->src, 0, "FUNC", "not found in the built module");
  return 0;
}

/* A routine the run needs: defined, and with arguments. */
static int need(const cable_autoeq *m, int r, const char *why, cable_error *err)
{
  if (m->nargs[r] > 0) return 0;
  return cable_error_set(err, CABLE_ERR_PLUGIN, m->src, m->def_line[r], autoeq_routine_name[r],
                         m->nargs[r] < 0 ? "the equation file does not define it, but %s"
                                         : "is a dummy without arguments, but %s",
                         why);
}

int autoeq_make_problem(cable_autoeq *m, const cable_constants *c, cable_error *err)
{
  if (c->ndim <= 0)
    return cable_error_set(err, CABLE_ERR_INPUT, m->src, 0, "NDIM", "equations from an AUTO file take NDIM from the "
                           "constants (there is no NDIM there)");
  char why[64];
  int rc = 0;
  snprintf(why, sizeof why, "NBC=%d", c->nbc);
  if (c->nbc > 0) rc = need(m, AE_BCND, why, err);
  snprintf(why, sizeof why, "NINT=%d", c->nint);
  if (!rc && c->nint > 0) rc = need(m, AE_ICND, why, err);
  if (!rc && c->irs == 0 && !c->irs_name[0] && !m->dat) rc = need(m, AE_STPNT, "the run starts from STPNT (IRS=0)", err);
  if (!rc) rc = autoeq_check_called(m, c, err);
  if (rc) return rc;
  m->ndim = c->ndim;
  m->nbc = c->nbc;
  m->nint = c->nint;
  m->npar = c->npar;
  m->nfpr0 = c->nbc + c->nint - c->ndim + 1;
  m->nicp = c->nicp < AUTOEQ_MAX_ICP ? c->nicp : AUTOEQ_MAX_ICP;
  for (int k = 0; k < m->nicp; k++) m->icp_tail[k] = c->icp[k] + 1;
  size_t nd = (size_t)m->ndim, np = (size_t)m->npar;
  size_t ns = nd * nd + nd * np + (size_t)m->nbc * (2 * nd + np) + (size_t)m->nint * (nd + np);
  if (ns > m->nscratch) {
    double *s = realloc(m->scratch, ns * sizeof *s);
    if (!s) return cable_error_set(err, CABLE_ERR_ALLOC, m->src, 0, "", "out of memory");
    m->scratch = s;
    m->nscratch = ns;
  }
  memset(m->scratch, 0, ns * sizeof *m->scratch);
  cable_problem *pb = &m->pb;
  memset(pb, 0, sizeof *pb);
  pb->abi_version = CABLE_PROBLEM_ABI;
  pb->struct_size = sizeof *pb;
  pb->name = m->name;
  pb->description = m->src;
  pb->ndim = m->ndim;
  pb->nbc = m->nbc;
  pb->nint = m->nint;
  pb->npar = 0;   /* AUTO's equations use any PAR(k) up to the run's NPAR */
  pb->func = ae_func;
  pb->bcnd = m->nbc > 0 ? ae_bcnd : NULL;
  pb->icnd = m->nint > 0 ? ae_icnd : NULL;
  pb->stpnt = (m->c_tab || m->nargs[AE_STPNT] > 0 || m->dat) ? ae_stpnt : NULL;
  pb->pvls = (m->c_tab || m->nargs[AE_PVLS] > 0) ? ae_pvls : NULL;
  /* AUTO's JAC: 1 the routines give derivatives (-1: only with respect to U) */
  pb->func_has_jac = pb->bcnd_has_jac = pb->icnd_has_jac = c->jac != 0;
  pb->params = m;
  return 0;
}

int autoeq_read_dat(cable_autoeq *m, const char *path, cable_error *err)
{
  free(m->dat);
  m->dat = NULL;
  m->ndat = 0;
  FILE *f = fopen(path, "r");
  if (!f) return cable_error_set(err, CABLE_ERR_IO, path, 0, "dat", "cannot open the start data: %s", strerror(errno));
  int w = m->ndim + 1, cap = 0, line = 0, rc = 0;
  char buf[8192];
  while (!rc && fgets(buf, sizeof buf, f)) {
    line++;
    char *p = buf, *end;
    while (isspace((unsigned char)*p)) p++;
    if (!*p || *p == '#') continue;
    if (m->ndat == cap) {
      cap = cap ? 2 * cap : 64;
      double *d = realloc(m->dat, (size_t)cap * (size_t)w * sizeof *d);
      if (!d) {
        rc = cable_error_set(err, CABLE_ERR_ALLOC, path, line, "dat", "out of memory");
        break;
      }
      m->dat = d;
    }
    double *row = m->dat + (size_t)m->ndat * (size_t)w;
    int k = 0;
    for (; k < w; k++) {
      errno = 0;
      row[k] = strtod(p, &end);
      if (end == p || !isfinite(row[k])) break;
      p = end;
    }
    while (isspace((unsigned char)*p)) p++;
    if (k < w || *p)
      rc = cable_error_set(err, CABLE_ERR_INPUT, path, line, "dat", "a row is t and U(1)..U(NDIM): %d finite numbers",
                           w);
    else if (m->ndat > 0 && !(row[0] > row[-w]))
      rc = cable_error_set(err, CABLE_ERR_INPUT, path, line, "dat", "t must increase from row to row");
    else
      m->ndat++;
  }
  fclose(f);
  if (!rc && m->ndat < 2) rc = cable_error_set(err, CABLE_ERR_INPUT, path, line, "dat", "needs at least two rows");
  if (rc) {
    free(m->dat);
    m->dat = NULL;
    m->ndat = 0;
    return rc;
  }
  /* AUTO rescales the data's t to [0, 1] */
  double t0 = m->dat[0], t1 = m->dat[(size_t)(m->ndat - 1) * (size_t)w];
  for (int k = 0; k < m->ndat; k++) m->dat[(size_t)k * (size_t)w] = (m->dat[(size_t)k * (size_t)w] - t0) / (t1 - t0);
  return 0;
}
