/* SPDX-License-Identifier: GPL-3.0-or-later */
/* curves(branch, i): the geometry of a braid solution along its stored
 * points, as numpy arrays for the Python package (Solution.strand2,
 * .contact, .pressure, ...; cable_braid_solution_curves), at the solution's own
 * t_k, so that they line up with sol['t'] and the components. */
#include "pycable.h"

#define NPY_NO_DEPRECATED_API NPY_1_7_API_VERSION
#define NO_IMPORT_ARRAY
#define PY_ARRAY_UNIQUE_SYMBOL cable_pycable_ARRAY_API
#include <numpy/arrayobject.h>

enum { CV_R1, CV_R2, CV_C, CV_P1, CV_P2, CV_SIGMA, CV_N };
static const char *const cv_names[CV_N] = {"strand1", "strand2", "contact", "p1", "p2", "sigma"};

PyObject *pyc_curves(PyObject *mod, PyObject *args)
{
  (void)mod;
  PyObject *br;
  int i;
  if (!PyArg_ParseTuple(args, "Oi", &br, &i)) return NULL;
  const cable_solution *s = pyc_solution_arg(br, i);
  if (!s) return NULL;
  npy_intp n = cable_solution_npts(s), dims[2] = {n, 3};
  PyObject *a[CV_N] = {NULL};
  int ok = 1;
  for (int k = 0; k < CV_N && ok; k++) {
    a[k] = PyArray_SimpleNew(k < CV_P1 ? 2 : 1, dims, NPY_DOUBLE);
    ok = a[k] != NULL;
  }
  PyObject *d = ok ? PyDict_New() : NULL;
  int rc = 0;
  if (d) {
    double *p[CV_N];
    for (int k = 0; k < CV_N; k++) p[k] = PyArray_DATA((PyArrayObject *)a[k]);
    Py_BEGIN_ALLOW_THREADS
    rc = cable_braid_solution_curves(s, p[CV_R1], p[CV_R2], p[CV_C], p[CV_P1], p[CV_P2], p[CV_SIGMA]);
    Py_END_ALLOW_THREADS
  }
  for (int k = 0; k < CV_N && d && !rc; k++)
    if (PyDict_SetItemString(d, cv_names[k], a[k]) < 0) {
      Py_CLEAR(d);
    }
  for (int k = 0; k < CV_N; k++) Py_XDECREF(a[k]);
  if (rc) {
    Py_XDECREF(d);
    cable_error err;
    cable_error_set(&err, rc, NULL, 0, NULL, "label %d is not a braid solution: it has no strands (%s)", s->lab,
                    cable_status_message(rc));
    return pyc_raise(rc, &err);
  }
  return d;
}
