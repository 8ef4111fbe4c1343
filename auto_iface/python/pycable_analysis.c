/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The numerical analysis of one braid solution and the pictures, for the
 * Python package: analyze (braid_analysis.h), the axis self-passages
 * between two solutions (axis_passages.h), the tube distance
 * (tube_distance.h), plot and render (cable_pictures.h). */
#include "pycable.h"

#include <math.h>
#include <string.h>


static int set_num(PyObject *d, const char *key, double x)
{
  PyObject *v = PyFloat_FromDouble(x);
  int rc = v ? PyDict_SetItemString(d, key, v) : -1;
  Py_XDECREF(v);
  return rc;
}

static int set_int(PyObject *d, const char *key, long x)
{
  PyObject *v = PyLong_FromLong(x);
  int rc = v ? PyDict_SetItemString(d, key, v) : -1;
  Py_XDECREF(v);
  return rc;
}

static int set_list(PyObject *d, const char *key, const double *x, int n)
{
  PyObject *l = PyList_New(n);
  for (int i = 0; l && i < n; i++) PyList_SET_ITEM(l, i, PyFloat_FromDouble(x[i]));
  int rc = l ? PyDict_SetItemString(d, key, l) : -1;
  Py_XDECREF(l);
  return rc;
}

static int psign_stored(const cable_braid_psign *p)
{
  return p->n < CABLE_BRAID_PSIGN_MAX ? p->n : CABLE_BRAID_PSIGN_MAX;
}

/* analyze(branch, i) -> dict of derived quantities (doc/scripts.md) */
PyObject *pyc_analyze(PyObject *mod, PyObject *args)
{
  (void)mod;
  PyObject *br;
  int i, stab = 0;
  if (!PyArg_ParseTuple(args, "Oi|i", &br, &i, &stab)) return NULL;
  const cable_solution *s = pyc_solution_arg(br, i);
  if (!s) return NULL;
  cable_braid_analysis *a = PyMem_Malloc(sizeof *a);
  if (!a) return PyErr_NoMemory();
  int rc;
  Py_BEGIN_ALLOW_THREADS
  rc = cable_braid_analysis_compute(s, a);
  Py_END_ALLOW_THREADS
  if (rc) {
    PyMem_Free(a);
    cable_error err;
    cable_error_set(&err, rc, NULL, 0, NULL, "label %d is not a closed braid solution (%s)", s->lab,
                    cable_status_message(rc));
    return pyc_raise(rc, &err);
  }
  const cable_knot_type_result *k = &a->topo.axis;
  PyObject *d = PyDict_New();
  PyObject *ov = d ? PyList_New(0) : NULL;
  int n = a->tube.noverlap < CABLE_TUBE_MAX_INTERVALS ? a->tube.noverlap : CABLE_TUBE_MAX_INTERVALS;
  for (int j = 0; ov && j < n; j++) {
    PyObject *iv = Py_BuildValue("[dd]", a->tube.overlap[j][0], a->tube.overlap[j][1]);
    if (!iv || PyList_Append(ov, iv) < 0) Py_CLEAR(ov);
    Py_XDECREF(iv);
  }
  PyObject *knot = d ? PyUnicode_FromString(k->name) : NULL;
  int bad = !d || !ov || !knot || set_num(d, "Lk", a->topo.lk) || set_num(d, "Tw", a->topo.tw) ||
            set_num(d, "Wr", a->topo.wr) || set_num(d, "Lk_defect", a->topo.lk_defect) ||
            PyDict_SetItemString(d, "knot", knot) || set_int(d, "hand", k->handedness) ||
            set_int(d, "crossings", k->crossing_number) || set_num(d, "lk_in_tube", a->topo.lk_in_tube) ||
            set_num(d, "closure_sign", a->topo.closure) || set_num(d, "pmin", fmin(a->pmin1, a->pmin2)) ||
            set_num(d, "pmin1", a->pmin1) || set_num(d, "pmax1", a->pmax1) || set_num(d, "pmin2", a->pmin2) ||
            set_num(d, "pmax2", a->pmax2) || set_int(d, "psign", a->psign1.n) || set_int(d, "psign2", a->psign2.n) ||
            set_list(d, "psign_s1", a->psign1.s, psign_stored(&a->psign1)) ||
            set_list(d, "psign_s2", a->psign2.s, psign_stored(&a->psign2)) ||
            set_list(d, "psign_sigma2", a->psign2.sigma, psign_stored(&a->psign2)) ||
            set_num(d, "dmin", a->tube.dmin) || set_num(d, "axis_dmin", a->tube.axis_dmin) ||
            set_int(d, "noverlap", a->tube.noverlap) || PyDict_SetItemString(d, "overlap", ov) ||
            set_num(d, "overlap_length", a->tube.overlap_length) ||
            set_num(d, "axis_kappa_max", a->tube.axis_kappa_max) || set_num(d, "drift", a->drift) ||
            set_num(d, "closure", a->closure) || set_num(d, "closure2", a->closure2) || set_num(d, "err", s->err_est);
  const double closure_sign = a->topo.closure;
  PyMem_Free(a);
  Py_XDECREF(ov);
  Py_XDECREF(knot);
  if (bad) {
    Py_XDECREF(d);
    return NULL;
  }
  if (stab) {
    /* the Morse index (doc/stability.md S7): 'index', 'nzero', 'sigma' */
    cable_stab_result r;
    cable_error err;
    /* a knot computed with eps13 free is a braid_knot_sym solution (the mode
       branches): its second variation has the row delta F2(0) = 0 (S7.3) */
    const cable_problem *ks = cable_problem_builtin("braid_knot_sym");
    int sym = 0;
    for (int j = 0; ks && ks->parnames && j < s->nfpr; j++)
      sym |= s->icp[j] >= 0 && s->icp[j] < ks->npar && ks->parnames[s->icp[j]] &&
             strcmp(ks->parnames[s->icp[j]], "eps13") == 0;
    const cable_problem *pb =
      cable_problem_builtin(closure_sign < 0 ? (sym ? "braid_knot_sym" : "braid_knot") : "braid_link");
    int st;
    Py_BEGIN_ALLOW_THREADS
    st = cable_stability_index(pb, s, 1, s->ncol, &r, &err);
    Py_END_ALLOW_THREADS
    if (st) {
      Py_DECREF(d);
      return pyc_raise(st, &err);
    }
    if (set_int(d, "index", r.index) || set_int(d, "nzero", r.nzero) || set_list(d, "sigma", r.eig, r.neig)) {
      Py_DECREF(d);
      return NULL;
    }
  }
  return d;
}

/* passages(branch, i, branch2, j) -> (count, net, tau_first) */
PyObject *pyc_passages(PyObject *mod, PyObject *args)
{
  (void)mod;
  PyObject *b1, *b2;
  int i, j;
  if (!PyArg_ParseTuple(args, "OiOi", &b1, &i, &b2, &j)) return NULL;
  const cable_solution *s1 = pyc_solution_arg(b1, i), *s2 = s1 ? pyc_solution_arg(b2, j) : NULL;
  if (!s2) return NULL;
  cable_axis_passages ap;
  int rc;
  Py_BEGIN_ALLOW_THREADS
  rc = cable_braid_axis_passages(s1, s2, &ap);
  Py_END_ALLOW_THREADS
  if (rc) {
    cable_error err;
    cable_error_set(&err, rc, NULL, 0, NULL, "labels %d and %d: cannot follow the braid axis between them (%s)",
                    s1->lab, s2->lab, cable_status_message(rc));
    return pyc_raise(rc, &err);
  }
  return Py_BuildValue("(iid)", ap.count, ap.net, ap.tau_first);
}

/* tube_dmin(branch, i) -> dmin */
PyObject *pyc_tube_dmin(PyObject *mod, PyObject *args)
{
  (void)mod;
  PyObject *b;
  int i;
  if (!PyArg_ParseTuple(args, "Oi", &b, &i)) return NULL;
  const cable_solution *s = pyc_solution_arg(b, i);
  if (!s) return NULL;
  cable_tube_distance_result td;
  int rc;
  Py_BEGIN_ALLOW_THREADS
  rc = cable_braid_tube_distance_solution(s, 0, &td);
  Py_END_ALLOW_THREADS
  if (rc) {
    cable_error err;
    cable_error_set(&err, rc, NULL, 0, NULL, "label %d is not a closed braid solution (%s)", s->lab,
                    cable_status_message(rc));
    return pyc_raise(rc, &err);
  }
  return PyFloat_FromDouble(td.dmin);
}

static int set_bytes(PyObject *d, const char *key, const double *x, size_t n)
{
  PyObject *v = PyBytes_FromStringAndSize((const char *)x, (Py_ssize_t)(n * sizeof(double)));
  int rc = v ? PyDict_SetItemString(d, key, v) : -1;
  Py_XDECREF(v);
  return rc;
}

/* strands(branch, i) -> {'n', 'closed', 'radius', 'r1', 'r2', 'p1', 'p2'}:
 * the strand centre lines [3n] and contact pressures [n] as bytes of
 * doubles (cable_solution_strands; numpy.frombuffer reads them) */
PyObject *pyc_strands(PyObject *mod, PyObject *args)
{
  (void)mod;
  PyObject *b;
  int i;
  if (!PyArg_ParseTuple(args, "Oi", &b, &i)) return NULL;
  const cable_solution *s = pyc_solution_arg(b, i);
  if (!s) return NULL;
  cable_strands st;
  int rc;
  Py_BEGIN_ALLOW_THREADS
  rc = cable_solution_strands(s, &st);
  Py_END_ALLOW_THREADS
  if (rc) {
    cable_error err;
    cable_error_set(&err, rc, NULL, 0, NULL, "label %d: no strands (%s)", s->lab, cable_status_message(rc));
    return pyc_raise(rc, &err);
  }
  size_t n = (size_t)st.n;
  PyObject *d = PyDict_New();
  int bad = !d || set_int(d, "n", st.n) || set_int(d, "closed", st.closed) || set_num(d, "radius", st.radius) ||
            set_bytes(d, "r1", st.r1, 3 * n) || set_bytes(d, "r2", st.r2, 3 * n) || set_bytes(d, "p1", st.p1, n) ||
            set_bytes(d, "p2", st.p2, n);
  cable_strands_free(&st);
  if (bad) {
    Py_XDECREF(d);
    return NULL;
  }
  return d;
}

static int set_ints(PyObject *d, const char *key, const int *x, int n)
{
  PyObject *l = PyList_New(n);
  for (int i = 0; l && i < n; i++) PyList_SET_ITEM(l, i, PyLong_FromLong(x[i]));
  int rc = l ? PyDict_SetItemString(d, key, l) : -1;
  Py_XDECREF(l);
  return rc;
}

/* bfile(path) -> [{'columns', 'br', 'pt', 'ty', 'lab', 'data'}, ...]: the
 * sections of a b-file (cable_bfile_read), every row; data holds the value
 * columns as bytes of doubles, column-major (column j: rows j*nrow ..) */
PyObject *pyc_bfile(PyObject *mod, PyObject *args)
{
  (void)mod;
  const char *path;
  if (!PyArg_ParseTuple(args, "s", &path)) return NULL;
  cable_error err;
  cable_error_clear(&err);
  cable_bfile *bf;
  Py_BEGIN_ALLOW_THREADS
  bf = cable_bfile_read(path, &err);
  Py_END_ALLOW_THREADS
  if (!bf) return pyc_raise(err.status ? err.status : CABLE_ERR_IO, &err);
  PyObject *out = PyList_New(0);
  for (int k = 0; out && k < bf->nbranch; k++) {
    const cable_bfile_branch *b = &bf->branch[k];
    PyObject *d = PyDict_New(), *cols = d ? PyList_New(b->ncol) : NULL;
    for (int j = 0; cols && j < b->ncol; j++) PyList_SET_ITEM(cols, j, PyUnicode_FromString(b->colname[j]));
    int bad = !cols || PyDict_SetItemString(d, "columns", cols) || set_ints(d, "br", b->br, b->nrow) ||
              set_ints(d, "pt", b->pt, b->nrow) || set_ints(d, "ty", b->ty, b->nrow) ||
              set_ints(d, "lab", b->lab, b->nrow) ||
              set_bytes(d, "data", b->data, (size_t)b->nrow * (size_t)b->ncol) || PyList_Append(out, d);
    Py_XDECREF(cols);
    Py_XDECREF(d);
    if (bad) Py_CLEAR(out);
  }
  cable_bfile_free(bf);
  return out;
}

#define PLOT_MAX_FILES 64
#define PLOT_MAX_MARKS 64

/* plot(out, [bfile, ...], x, y, [(x, y, text[, filled]), ...], title) */
PyObject *pyc_plot(PyObject *mod, PyObject *args)
{
  (void)mod;
  const char *out, *x, *y, *title;
  PyObject *files, *marks;
  if (!PyArg_ParseTuple(args, "sOzzOz", &out, &files, &x, &y, &marks, &title)) return NULL;
  PyObject *ff = PySequence_Fast(files, "plot: a list of b-file names");
  PyObject *mf = ff ? PySequence_Fast(marks, "plot: a list of marks") : NULL;
  if (!mf) {
    Py_XDECREF(ff);
    return NULL;
  }
  Py_ssize_t nf = PySequence_Fast_GET_SIZE(ff), nm = PySequence_Fast_GET_SIZE(mf);
  PyObject *ret = NULL;
  if (nf < 1 || nf > PLOT_MAX_FILES || nm > PLOT_MAX_MARKS) {
    PyErr_Format(PyExc_ValueError, "plot: 1 to %d b-files and at most %d marks", PLOT_MAX_FILES, PLOT_MAX_MARKS);
    goto done;
  }
  const char *bf[PLOT_MAX_FILES];
  cable_plot_annotation ann[PLOT_MAX_MARKS];
  for (Py_ssize_t k = 0; k < nf; k++)
    if (!(bf[k] = PyUnicode_AsUTF8(PySequence_Fast_GET_ITEM(ff, k)))) goto done;
  for (Py_ssize_t k = 0; k < nm; k++) {
    ann[k].filled = 0;
    /* (x, y, text) or (x, y, text, filled) */
    if (!PyArg_ParseTuple(PySequence_Fast_GET_ITEM(mf, k), "dds|p", &ann[k].x, &ann[k].y, &ann[k].text,
                          &ann[k].filled))
      goto done;
  }
  cable_error err;
  cable_error_clear(&err);
  int rc;
  Py_BEGIN_ALLOW_THREADS
  rc = cable_plot_files(NULL, bf, (int)nf, x, y, ann, (int)nm, title, out, &err);
  Py_END_ALLOW_THREADS
  if (rc) pyc_raise(rc, &err);
  else ret = Py_NewRef(Py_None);
done:
  Py_DECREF(ff);
  Py_DECREF(mf);
  return ret;
}

/* render(branch, i, out, view (x, y, z) or None, size, thicken, pressure, vtp, ply) */
PyObject *pyc_render(PyObject *mod, PyObject *args)
{
  (void)mod;
  PyObject *b, *view;
  int i, size, pressure;
  double thicken;
  const char *out, *vtp, *ply;
  if (!PyArg_ParseTuple(args, "OizOidpzz", &b, &i, &out, &view, &size, &thicken, &pressure, &vtp, &ply)) return NULL;
  const cable_solution *s = pyc_solution_arg(b, i);
  if (!s) return NULL;
  cable_render_options o;
  memset(&o, 0, sizeof o);
  if (view != Py_None && !PyArg_ParseTuple(view, "ddd", &o.view_dir[0], &o.view_dir[1], &o.view_dir[2])) return NULL;
  o.width = o.height = size;
  o.thicken = thicken;
  if (pressure) o.colormap = CABLE_RENDER_COLORMAP_DIVERGING;
  cable_error err;
  cable_error_clear(&err);
  int rc;
  Py_BEGIN_ALLOW_THREADS
  rc = cable_render_solution(s, &o, out, vtp, ply, &err);
  Py_END_ALLOW_THREADS
  if (rc) return pyc_raise(rc, &err);
  Py_RETURN_NONE;
}
