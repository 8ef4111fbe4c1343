/* SPDX-License-Identifier: GPL-3.0-or-later */
/* cable._cable.Branch: one computed branch, read-only.  Its points (the
 * b-file rows) and labelled solutions come out as numpy arrays. */
#include "pycable.h"

#define NPY_NO_DEPRECATED_API NPY_1_7_API_VERSION
#define NO_IMPORT_ARRAY
#define PY_ARRAY_UNIQUE_SYMBOL cable_pycable_ARRAY_API
#include <numpy/arrayobject.h>

static void branch_dealloc(PyObject *self)
{
  cable_branch_decref(((pyc_branch *)self)->b);
  Py_TYPE(self)->tp_free(self);
}

PyObject *pyc_branch_wrap(cable_branch *b)
{
  pyc_branch *o = PyObject_New(pyc_branch, &pyc_branch_type);
  if (!o) {
    cable_branch_decref(b);
    return NULL;
  }
  o->b = b;
  return (PyObject *)o;
}

PyObject *pyc_branch_list(cable_branch **list, int n)
{
  PyObject *out = PyList_New(n);
  for (int k = 0; k < n; k++) {
    PyObject *o = out ? pyc_branch_wrap(list[k]) : NULL;
    list[k] = NULL;
    if (!o) {
      cable_branch_list_free(list, n);
      Py_XDECREF(out);
      return NULL;
    }
    PyList_SET_ITEM(out, k, o);
  }
  cable_branch_list_free(list, n);
  return out;
}

int pyc_branches_from(PyObject *seq, cable_branch ***out, int *n)
{
  *out = NULL;
  *n = 0;
  PyObject *fast = PySequence_Fast(seq, "a list of branches expected");
  if (!fast) return -1;
  Py_ssize_t m = PySequence_Fast_GET_SIZE(fast);
  *out = PyMem_Calloc((size_t)(m > 0 ? m : 1), sizeof **out);
  if (!*out) {
    Py_DECREF(fast);
    PyErr_NoMemory();
    return -1;
  }
  for (Py_ssize_t k = 0; k < m; k++) {
    PyObject *o = PySequence_Fast_GET_ITEM(fast, k);
    if (!PyObject_TypeCheck(o, &pyc_branch_type)) {
      Py_DECREF(fast);
      PyMem_Free(*out);
      *out = NULL;
      PyErr_SetString(PyExc_TypeError, "a list of branches expected");
      return -1;
    }
    (*out)[k] = ((pyc_branch *)o)->b;
  }
  *n = (int)m;
  Py_DECREF(fast);
  return 0;
}

const cable_solution *pyc_solution_arg(PyObject *branch, int i)
{
  if (!PyObject_TypeCheck(branch, &pyc_branch_type)) {
    PyErr_SetString(PyExc_TypeError, "a branch expected");
    return NULL;
  }
  const cable_branch *b = ((pyc_branch *)branch)->b;
  const cable_solution *s = cable_branch_solution(b, i);
  if (!s) PyErr_Format(PyExc_IndexError, "solution %d of a branch with %d", i, cable_branch_nsolutions(b));
  return s;
}

/* A new 1-d double array copied from x[0..n-1]. */
static PyObject *array1(const double *x, npy_intp n)
{
  PyObject *a = PyArray_SimpleNew(1, &n, NPY_DOUBLE);
  if (a && n > 0) memcpy(PyArray_DATA((PyArrayObject *)a), x, (size_t)n * sizeof *x);
  return a;
}

/* Points of the branch: {'par': (npt, npar), 'L2-NORM', 'MAX U': (npt, ndim),
 * 'measure' (IPLT's, the b-file's second column), 'PT', 'LAB', 'TY' (codes), 'BR'}. */
static PyObject *branch_points(PyObject *self, PyObject *unused)
{
  (void)unused;
  const cable_branch *b = ((pyc_branch *)self)->b;
  npy_intp npt = cable_branch_npoints(b), npar = 0, ndim = 0;
  for (int i = 0; i < npt; i++) {
    if (cable_branch_point(b, i)->npar > npar) npar = cable_branch_point(b, i)->npar;
    if (cable_branch_point(b, i)->umax && cable_branch_point(b, i)->ndim > ndim) ndim = cable_branch_point(b, i)->ndim;
  }
  npy_intp dims[2] = {npt, npar}, udims[2] = {npt, ndim};
  PyObject *umax = PyArray_ZEROS(2, udims, NPY_DOUBLE, 0), *meas = PyArray_SimpleNew(1, &npt, NPY_DOUBLE);
  PyObject *par = PyArray_ZEROS(2, dims, NPY_DOUBLE, 0), *l2 = PyArray_SimpleNew(1, &npt, NPY_DOUBLE);
  PyObject *pt = PyArray_SimpleNew(1, &npt, NPY_LONG), *lab = PyArray_SimpleNew(1, &npt, NPY_LONG);
  PyObject *ty = PyArray_SimpleNew(1, &npt, NPY_LONG), *br = PyArray_SimpleNew(1, &npt, NPY_LONG);
  PyObject *d = NULL;
  if (par && l2 && pt && lab && ty && br && umax && meas) {
    double *P = PyArray_DATA((PyArrayObject *)par), *L = PyArray_DATA((PyArrayObject *)l2);
    double *U = PyArray_DATA((PyArrayObject *)umax), *M = PyArray_DATA((PyArrayObject *)meas);
    long *T = PyArray_DATA((PyArrayObject *)pt), *B = PyArray_DATA((PyArrayObject *)lab);
    long *Y = PyArray_DATA((PyArrayObject *)ty), *R = PyArray_DATA((PyArrayObject *)br);
    for (npy_intp i = 0; i < npt; i++) {
      const cable_point *p = cable_branch_point(b, (int)i);
      for (int k = 0; k < p->npar; k++) P[i * npar + k] = p->par[k];
      for (int k = 0; p->umax && k < p->ndim && k < ndim; k++) U[i * ndim + k] = p->umax[k];
      L[i] = p->l2norm;
      M[i] = p->measure;
      T[i] = p->pt;
      B[i] = p->lab;
      Y[i] = p->itp;
      R[i] = p->ibr;
    }
    d = Py_BuildValue("{sOsOsOsOsOsOsOsO}", "par", par, "L2-NORM", l2, "MAX U", umax, "measure", meas, "PT", pt,
                      "LAB", lab, "TY", ty, "BR", br);
  }
  Py_XDECREF(umax);
  Py_XDECREF(meas);
  Py_XDECREF(par);
  Py_XDECREF(l2);
  Py_XDECREF(pt);
  Py_XDECREF(lab);
  Py_XDECREF(ty);
  Py_XDECREF(br);
  return d;
}

/* Solution i: {'LAB', 'BR', 'PT', 'TY', 'itp', 'par', 't', 'u' (npts, ndim),
 * 'ntst', 'ncol', 'icp', 'err'}. */
static PyObject *branch_solution(PyObject *self, PyObject *arg)
{
  int i = (int)PyLong_AsLong(arg);
  if (i == -1 && PyErr_Occurred()) return NULL;
  const cable_solution *s = pyc_solution_arg(self, i);
  if (!s) return NULL;
  npy_intp n = cable_solution_npts(s), dims[2] = {n, s->ndim};
  PyObject *par = array1(s->par, s->npar), *t = array1(s->t, n), *u = PyArray_SimpleNew(2, dims, NPY_DOUBLE);
  PyObject *icp = PyList_New(s->nfpr), *d = NULL;
  for (int k = 0; icp && k < s->nfpr; k++) PyList_SET_ITEM(icp, k, PyLong_FromLong(s->icp[k] + 1));
  if (par && t && u && icp) {
    memcpy(PyArray_DATA((PyArrayObject *)u), s->u, (size_t)(n * s->ndim) * sizeof(double));
    d = Py_BuildValue("{sisisisssisOsOsOsisisOsd}", "LAB", s->lab, "BR", s->ibr, "PT", s->ntot, "TY",
                      cable_type_name(s->itp), "itp", s->itp, "par", par, "t", t, "u", u, "ntst", s->ntst, "ncol",
                      s->ncol, "icp", icp, "err", s->err_est);
  }
  Py_XDECREF(par);
  Py_XDECREF(t);
  Py_XDECREF(u);
  Py_XDECREF(icp);
  return d;
}

/* Labels, types and the parameters of the labelled solutions, cheaply:
 * [(LAB, TY, BR, PT, par ndarray, note or None, BP kind), ...]; the kind is
 * the detector's (cable_solution.bp_kind): 'simple', 'double', 'pair', or ''
 * (not a BP, or read from an s-file without its d-file, which keeps it). */
static PyObject *branch_labels(PyObject *self, PyObject *unused)
{
  (void)unused;
  const cable_branch *b = ((pyc_branch *)self)->b;
  int n = cable_branch_nsolutions(b);
  PyObject *out = PyList_New(n);
  for (int i = 0; out && i < n; i++) {
    const cable_solution *s = cable_branch_solution(b, i);
    const char *kind = cable_bp_kind_name(s->bp_kind);
    PyObject *par = array1(s->par, s->npar);
    PyObject *t = par ? Py_BuildValue("(isiiNzs)", s->lab, cable_type_name(s->itp), s->ibr, s->ntot, par,
                                      cable_branch_solution_note(b, i), kind)
                      : NULL;
    if (!t) {
      Py_DECREF(out);
      return NULL;
    }
    PyList_SET_ITEM(out, i, t);
  }
  return out;
}

/* Names of PAR(1..n) ("" unnamed) and of U(1..ndim). */
static PyObject *names_list(const char (*names)[CABLE_NAME_LEN], int n)
{
  PyObject *out = PyList_New(n);
  for (int k = 0; out && k < n; k++) {
    PyObject *s = PyUnicode_FromString(names[k]);
    if (!s) {
      Py_DECREF(out);
      return NULL;
    }
    PyList_SET_ITEM(out, k, s);
  }
  return out;
}

static PyObject *branch_get_parnames(PyObject *self, void *closure)
{
  (void)closure;
  const cable_branch *b = ((pyc_branch *)self)->b;
  int n = 0;
  for (int i = 0; i < cable_branch_npoints(b); i++)
    if (cable_branch_point(b, i)->npar > n) n = cable_branch_point(b, i)->npar;
  for (int i = 0; i < cable_branch_nsolutions(b); i++)
    if (cable_branch_solution(b, i)->npar > n) n = cable_branch_solution(b, i)->npar;
  return names_list(cable_branch_names(b)->par, n < CABLE_NAMES_MAX ? n : CABLE_NAMES_MAX);
}

static PyObject *branch_get_unames(PyObject *self, void *closure)
{
  (void)closure;
  const cable_branch *b = ((pyc_branch *)self)->b;
  int n = cable_branch_nsolutions(b) > 0 ? cable_branch_solution(b, 0)->ndim
          : cable_branch_npoints(b) > 0   ? cable_branch_point(b, 0)->ndim
                                          : 0;
  return names_list(cable_branch_names(b)->u, n < CABLE_NAMES_MAX ? n : CABLE_NAMES_MAX);
}

static PyObject *branch_get_int(PyObject *self, void *closure)
{
  const cable_branch *b = ((pyc_branch *)self)->b;
  const char *what = closure;
  long v = strcmp(what, "ibr") == 0   ? cable_branch_number(b)
           : strcmp(what, "npt") == 0 ? cable_branch_npoints(b)
                                      : cable_branch_nsolutions(b);
  return PyLong_FromLong(v);
}

static PyObject *branch_get_str(PyObject *self, void *closure)
{
  const cable_branch *b = ((pyc_branch *)self)->b;
  if (strcmp(closure, "e") == 0) return PyUnicode_FromString(cable_branch_problem(b));
  if (strcmp(closure, "end_status") == 0) {
    int st = cable_branch_end_status(b);
    if (st) return PyUnicode_FromString(cable_status_name(st));
    Py_RETURN_NONE;
  }
  if (cable_branch_end_note(b)) return PyUnicode_FromString(cable_branch_end_note(b));
  Py_RETURN_NONE;
}

/* The principal continuation parameter (1-based, AUTO's ICP(1)) of the branch's constants. */
static PyObject *branch_get_icp(PyObject *self, void *closure)
{
  (void)closure;
  const cable_constants *c = cable_branch_constants(((pyc_branch *)self)->b);
  PyObject *out = PyList_New(c->nicp);
  for (int k = 0; out && k < c->nicp; k++) PyList_SET_ITEM(out, k, PyLong_FromLong(c->icp[k] + 1));
  return out;
}

/* constants() -> dict: the constants the branch was computed with (AUTO's s.c) */
static PyObject *branch_constants(PyObject *self, PyObject *noargs)
{
  (void)noargs;
  const cable_branch *b = ((pyc_branch *)self)->b;
  return pyc_constants_dict(cable_branch_constants(b), cable_branch_names(b), cable_branch_problem(b));
}

/* directions() -> [dict, ...] or None: the branch directions the run's
 * switch found at a double branch point (cable_branch_switch_directions) */
static PyObject *branch_directions(PyObject *self, PyObject *noargs)
{
  (void)noargs;
  cable_branch_dir d[CABLE_MAX_BRANCHES];
  int order = 0, n = cable_branch_switch_directions(((pyc_branch *)self)->b, d, CABLE_MAX_BRANCHES, &order);
  if (n < 0) Py_RETURN_NONE;
  PyObject *out = PyList_New(n);
  for (int k = 0; out && k < n; k++) {
    PyObject *e = Py_BuildValue("{s:i,s:d,s:(ddd),s:d,s:(dd),s:(dd),s:d,s:i,s:i,s:O,s:O,s:i}", "BRANCH", k + 1, "phi",
                                d[k].phi, "a", d[k].a[0], d[k].a[1], d[k].a[2], "mu", d[k].mu, "L", d[k].L[0],
                                d[k].L[1], "N", d[k].N[0], d[k].N[1], "dg", d[k].dg, "multiplicity",
                                d[k].multiplicity, "sym", d[k].sym, "symmetric", d[k].sym ? Py_True : Py_False,
                                "restricted", d[k].restricted ? Py_True : Py_False, "order", order);
    if (!e) {
      Py_DECREF(out);
      return NULL;
    }
    PyList_SET_ITEM(out, k, e);
  }
  return out;
}

static PyMethodDef branch_methods[] = {
    {"directions", branch_directions, METH_NOARGS,
     "the branch directions of the run's switch at a double branch point (list of dicts), None: none"},
    {"points", branch_points, METH_NOARGS, "the branch's points (b-file rows) as numpy arrays"},
    {"solution", branch_solution, METH_O, "labelled solution i: a dict of its data (numpy arrays)"},
    {"constants", branch_constants, METH_NOARGS, "the constants of the branch's run as a dict (AUTO's s.c)"},
    {"labels", branch_labels, METH_NOARGS, "[(LAB, TY, BR, PT, par), ...] of the labelled solutions"},
    {NULL, NULL, 0, NULL}};

static char k_ibr[] = "ibr", k_npt[] = "npt", k_nsol[] = "nsol", k_e[] = "e", k_end[] = "end",
            k_end_status[] = "end_status";

static PyGetSetDef branch_getset[] = {
    {"ibr", branch_get_int, NULL, "branch number", k_ibr},
    {"npt", branch_get_int, NULL, "number of points", k_npt},
    {"nsol", branch_get_int, NULL, "number of labelled solutions", k_nsol},
    {"e", branch_get_str, NULL, "the problem's name", k_e},
    {"end_note", branch_get_str, NULL, "why the branch ended abnormally (None: normal end)", k_end},
    {"end_status", branch_get_str, NULL,
     "how the run ended, the status's name ('CABLE_END_NMX', 'CABLE_ERR_DSMIN', ...); None: not a run's",
     k_end_status},
    {"parnames", branch_get_parnames, NULL, "names of PAR(1), PAR(2), ... ('' unnamed)", NULL},
    {"unames", branch_get_unames, NULL, "names of U(1), U(2), ... ('' unnamed)", NULL},
    {"icp", branch_get_icp, NULL, "the run's ICP list (1-based)", NULL},
    {NULL, NULL, NULL, NULL, NULL}};

PyTypeObject pyc_branch_type = {
    PyVarObject_HEAD_INIT(NULL, 0).tp_name = "cable._cable.Branch",
    .tp_basicsize = sizeof(pyc_branch),
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "one computed branch (immutable; shared between results)",
    .tp_dealloc = branch_dealloc,
    .tp_methods = branch_methods,
    .tp_getset = branch_getset,
};
