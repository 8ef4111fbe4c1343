/* SPDX-License-Identifier: GPL-3.0-or-later */
/* cable._cable: the C side of the Python package (python/cable).  A thin
 * layer over the session (cable_session.h) and the analysis of one braid
 * solution: it converts arguments, releases the GIL around runs, maps
 * statuses to cable.CableError with the library's message, and owns each
 * branch in one Python object.  Everything convenient (label selection,
 * iteration, AUTO's commands, the scene tables) is Python on top.
 *
 *   Session(dir)            a runner: run, load, save, loadbd, transform
 *   Branch                  one computed branch: points(), solution(i), ...
 *   analyze(br, i)          dict: Lk, Tw, Wr, knot type, pressure, tube distance ...
 *   passages(br, i, j)      self-passages of the braid axis between two solutions
 *   tube_dmin(br, i)        closest approach of the strand tubes / Delta
 *   plot(...), render(...)  pictures (graphics/)
 *   type_name(itp)          AUTO's two-letter point type
 *   blas_single_thread()    the application's BLAS setting (cable_blas_single_thread) */
#include "pycable.h"

#define NPY_NO_DEPRECATED_API NPY_1_7_API_VERSION
#define PY_ARRAY_UNIQUE_SYMBOL cable_pycable_ARRAY_API
#include <numpy/arrayobject.h>

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>


/* ---- errors ------------------------------------------------------------------ */

static PyObject *cable_error_type;   /* cable.CableError, created once at import */

/* The class of cable.errors that is also the built-in a Python program
 * catches for this kind of error (python/cable/errors.py), or NULL for
 * CableError itself: a bad value (ValueError), a missing argument
 * (TypeError), no such label, key or problem (KeyError), a file the error
 * names that does not exist (FileNotFoundError). */
static const char *error_class(int status, const cable_error *err)
{
  switch (status) {
  case CABLE_ERR_INPUT:
  case CABLE_ERR_PARSE:
  case CABLE_ERR_RANGE:
  case CABLE_ERR_SIZE:
    return "CableValueError";
  case CABLE_ERR_NULL:
    return "CableTypeError";
  case CABLE_ERR_NOTFOUND:
    return "CableKeyError";
  case CABLE_ERR_IO:
    if (err && err->file[0] && access(err->file, F_OK) != 0 && errno == ENOENT) return "CableFileNotFoundError";
    return NULL;
  default:
    return NULL;
  }
}

/* cable.errors' class by name, or CableError when the module is not there
 * (the extension used on its own); a new reference */
static PyObject *error_type(const char *name)
{
  PyObject *type = NULL;
  PyObject *mod = name ? PyImport_ImportModule("cable.errors") : NULL;
  if (mod) type = PyObject_GetAttrString(mod, name);
  Py_XDECREF(mod);
  if (!type || !PyType_Check(type) || PyObject_IsSubclass(type, cable_error_type) != 1) {
    PyErr_Clear();
    Py_XDECREF(type);
    type = cable_error_type;
    Py_INCREF(type);
  }
  return type;
}

PyObject *pyc_raise(int status, const cable_error *err)
{
  if (status == CABLE_ERR_INTERRUPTED && PyErr_Occurred()) return NULL;   /* KeyboardInterrupt */
  char buf[1400];
  const char *msg = err && err->msg[0] ? cable_error_format(err, buf, sizeof buf) : cable_status_message(status);
  PyObject *type = error_type(error_class(status, err));
  PyObject *exc = PyObject_CallFunction(type, "s", msg);
  PyObject *st = exc ? PyLong_FromLong(status) : NULL;
  if (st && PyObject_SetAttrString(exc, "status", st) == 0) PyErr_SetObject(type, exc);
  Py_XDECREF(st);
  Py_XDECREF(exc);
  Py_DECREF(type);
  return NULL;
}

/* ---- module -------------------------------------------------------------------- */

/* A process that runs tasks side by side with others (a Dask worker of
 * cable.atlas) makes the choice the cable program makes at start: one BLAS
 * thread (or CABLE_BLAS_THREADS), see cable_blas_single_thread. */
static PyObject *py_blas_single_thread(PyObject *mod, PyObject *unused)
{
  (void)mod;
  (void)unused;
  cable_blas_single_thread();
  Py_RETURN_NONE;
}

static PyObject *py_type_name(PyObject *mod, PyObject *arg)
{
  (void)mod;
  long itp = PyLong_AsLong(arg);
  if (itp == -1 && PyErr_Occurred()) return NULL;
  return PyUnicode_FromString(cable_type_name((int)itp));
}

static PyMethodDef module_methods[] = {
    {"type_name", py_type_name, METH_O, "AUTO's two-letter name of a point type code"},
    {"blas_single_thread", py_blas_single_thread, METH_NOARGS,
     "blas_single_thread(): ask OpenBLAS for one thread (CABLE_BLAS_THREADS=n: n), process-wide"},
    {"analyze", (PyCFunction)(void (*)(void))pyc_analyze, METH_VARARGS, "analyze(branch, i) -> dict"},
    {"passages", (PyCFunction)(void (*)(void))pyc_passages, METH_VARARGS,
     "passages(branch, i, j) -> (count, net, tau_first): self-passages of the braid axis"},
    {"tube_dmin", (PyCFunction)(void (*)(void))pyc_tube_dmin, METH_VARARGS,
     "tube_dmin(branch, i) -> closest approach of non-adjacent strand parts / Delta"},
    {"curves", (PyCFunction)(void (*)(void))pyc_curves, METH_VARARGS,
     "curves(branch, i) -> dict of numpy arrays at the stored points: strand1, strand2, contact (n x 3), p1, p2, sigma"},
    {"plot", (PyCFunction)(void (*)(void))pyc_plot, METH_VARARGS,
     "plot(out, bfiles, x, y, marks, title): bifurcation diagram of b-files"},
    {"bfile", (PyCFunction)(void (*)(void))pyc_bfile, METH_VARARGS,
     "bfile(path) -> the sections of a b-file, every row (columns, br, pt, ty, lab, data)"},
    {"strands", (PyCFunction)(void (*)(void))pyc_strands, METH_VARARGS,
     "strands(branch, i) -> the strand centre lines and contact pressures (bytes of doubles)"},
    {"render", (PyCFunction)(void (*)(void))pyc_render, METH_VARARGS,
     "render(branch, i, out, view, size, thicken, pressure, vtp, ply)"},
    {"constants_layout", pyc_constants_layout, METH_NOARGS,
     "constants_layout() -> the keys of each line of printed constants (cable/cable_constants_keys.h)"},
    {NULL, NULL, 0, NULL}};

static struct PyModuleDef module_def = {PyModuleDef_HEAD_INIT, "cable._cable",
                                        "The C side of the cable package (auto_iface/python/pycable_*.c).", -1,
                                        module_methods, NULL, NULL, NULL, NULL};

PyMODINIT_FUNC PyInit__cable(void);
PyMODINIT_FUNC PyInit__cable(void)
{
  import_array();
  if (PyType_Ready(&pyc_branch_type) < 0 || PyType_Ready(&pyc_session_type) < 0) return NULL;
  PyObject *m = PyModule_Create(&module_def);
  if (!m) return NULL;
  cable_error_type = PyErr_NewExceptionWithDoc(
      "cable.CableError",
      "An error of cable's library: the message names file, line and key; .status is the cable_status code.",
      PyExc_RuntimeError, NULL);
  if (!cable_error_type || PyModule_AddObjectRef(m, "CableError", cable_error_type) < 0 ||
      PyModule_AddObjectRef(m, "Branch", (PyObject *)&pyc_branch_type) < 0 ||
      PyModule_AddObjectRef(m, "Session", (PyObject *)&pyc_session_type) < 0 ||
      PyModule_AddIntConstant(m, "ERR_INTERRUPTED", CABLE_ERR_INTERRUPTED) < 0) {
    Py_DECREF(m);
    return NULL;
  }
  return m;
}
