/* cable._cable.Session: AUTO's runner on cable's engine (cable_session.h).
 * Runs release the GIL; after every computed point the session takes it back
 * for a moment to run Python's signal handlers, so Ctrl-C (KeyboardInterrupt)
 * stops a run at the next point, before anything of it is written. */
#include "pycable.h"

#include <stdio.h>
#include <stdlib.h>

typedef struct pyc_session {
  PyObject_HEAD
  cable_session *s;
  PyThreadState *ts;   /* the thread's state while a run has released the GIL */
} pyc_session;

/* The session's interrupt check: Python's pending signal handlers, with the GIL. */
static int session_interrupt(void *ctx)
{
  pyc_session *self = ctx;
  if (!self->ts) return 0;
  PyEval_RestoreThread(self->ts);
  int stop = PyErr_CheckSignals() < 0;
  self->ts = PyEval_SaveThread();
  return stop;
}

static int session_init(PyObject *obj, PyObject *args, PyObject *kw)
{
  pyc_session *self = (pyc_session *)obj;
  if (!PyArg_ParseTuple(args, "") || (kw && PyDict_Size(kw) > 0)) {
    if (!PyErr_Occurred()) PyErr_SetString(PyExc_TypeError, "Session() takes no arguments");
    return -1;
  }
  if (self->s) return 0;
  cable_session_options o;
  cable_session_options_init(&o);
  o.dir = NULL;   /* the current directory: the Python layer changes it (AUTO's cd) */
  o.interrupt = session_interrupt;
  o.interrupt_ctx = self;
  self->s = cable_session_alloc(&o);
  if (!self->s) {
    PyErr_NoMemory();
    return -1;
  }
  return 0;
}

static void session_dealloc(PyObject *obj)
{
  cable_session_free(((pyc_session *)obj)->s);
  Py_TYPE(obj)->tp_free(obj);
}

/* A str argument or None. */
static int opt_str(PyObject *o, const char **out)
{
  *out = NULL;
  if (o == Py_None) return 0;
  *out = PyUnicode_AsUTF8(o);
  return *out ? 0 : -1;
}

typedef struct run_inputs {
  cable_run_args a;
  cable_branch **branches;
  const char **over;
  PyObject *over_fast;
} run_inputs;

static void inputs_free(run_inputs *in)
{
  PyMem_Free(in->branches);
  PyMem_Free(in->over);
  Py_XDECREF(in->over_fast);
}

/* (start, sol, mbr, mlab, name, e, c, s, sv, ap, over): start a Branch with
 * sol >= 0 (a solution, mbr and mlab the largest branch number and label of
 * the result it was taken from), a list of branches (a result), or None;
 * name, e, c, s, sv, ap str or None; over a list of "KEY=VALUE" statements. */
static int inputs_parse(PyObject *args, run_inputs *in)
{
  memset(in, 0, sizeof *in);
  PyObject *start, *name, *e, *c, *s, *sv, *ap, *over;
  int sol, mbr, mlab;
  if (!PyArg_ParseTuple(args, "OiiiOOOOOOO", &start, &sol, &mbr, &mlab, &name, &e, &c, &s, &sv, &ap, &over))
    return -1;
  if (PyObject_TypeCheck(start, &pyc_branch_type) && sol >= 0) {
    in->a.sol_branch = ((pyc_branch *)start)->b;
    in->a.sol_index = sol;
    in->a.sol_mbr = mbr;
    in->a.sol_mlab = mlab;
  } else if (start != Py_None) {
    if (pyc_branches_from(start, &in->branches, &in->a.nbranch) < 0) return -1;
    in->a.branches = in->branches;
  }
  if (opt_str(name, &in->a.name) || opt_str(e, &in->a.e) || opt_str(c, &in->a.c) || opt_str(s, &in->a.s) ||
      opt_str(sv, &in->a.sv) || opt_str(ap, &in->a.ap))
    return -1;
  in->over_fast = PySequence_Fast(over, "overrides: a list of str");
  if (!in->over_fast) return -1;
  Py_ssize_t n = PySequence_Fast_GET_SIZE(in->over_fast);
  in->over = PyMem_Calloc((size_t)(n > 0 ? n : 1), sizeof *in->over);
  if (!in->over) {
    PyErr_NoMemory();
    return -1;
  }
  for (Py_ssize_t k = 0; k < n; k++)
    if (!(in->over[k] = PyUnicode_AsUTF8(PySequence_Fast_GET_ITEM(in->over_fast, k)))) return -1;
  in->a.nover = (int)n;
  in->a.over = in->over;
  return 0;
}

/* run(start, sol, mbr, mlab, name, e, c, s, sv, ap, over) -> Branch */
static PyObject *session_run(PyObject *obj, PyObject *args)
{
  pyc_session *self = (pyc_session *)obj;
  run_inputs in;
  if (inputs_parse(args, &in) < 0) {
    inputs_free(&in);
    return NULL;
  }
  cable_branch *b = NULL;
  cable_error err;
  cable_error_clear(&err);
  fflush(stdout);
  self->ts = PyEval_SaveThread();
  int rc = cable_session_run(self->s, &in.a, &b, &err);
  PyEval_RestoreThread(self->ts);
  self->ts = NULL;
  fflush(stdout);
  inputs_free(&in);
  return rc ? pyc_raise(rc, &err) : pyc_branch_wrap(b);
}

/* load(start, sol, mbr, mlab, name, e, c, s, sv, ap, over) -> Branch with one solution */
static PyObject *session_load(PyObject *obj, PyObject *args)
{
  pyc_session *self = (pyc_session *)obj;
  run_inputs in;
  if (inputs_parse(args, &in) < 0) {
    inputs_free(&in);
    return NULL;
  }
  cable_branch *b = NULL;
  cable_error err;
  cable_error_clear(&err);
  int rc = cable_session_load(self->s, &in.a, &b, &err);
  inputs_free(&in);
  if (!rc && !b) Py_RETURN_NONE;   /* no solution: the runner's constants were set */
  return rc ? pyc_raise(rc, &err) : pyc_branch_wrap(b);
}

/* save(branches, sol, name, append) */
static PyObject *session_save(PyObject *obj, PyObject *args)
{
  pyc_session *self = (pyc_session *)obj;
  PyObject *seq;
  int sol, append;
  const char *name;
  if (!PyArg_ParseTuple(args, "Oisp", &seq, &sol, &name, &append)) return NULL;
  cable_branch **br;
  int n;
  if (pyc_branches_from(seq, &br, &n) < 0) return NULL;
  cable_error err;
  cable_error_clear(&err);
  fflush(stdout);
  int rc = cable_session_save(self->s, br, n, sol, name, append, &err);
  fflush(stdout);
  PyMem_Free(br);
  if (rc) return pyc_raise(rc, &err);
  Py_RETURN_NONE;
}

/* loadbd(name) -> [Branch, ...] */
static PyObject *session_loadbd(PyObject *obj, PyObject *args)
{
  pyc_session *self = (pyc_session *)obj;
  const char *name;
  if (!PyArg_ParseTuple(args, "s", &name)) return NULL;
  cable_branch **list = NULL;
  int n = 0;
  cable_error err;
  cable_error_clear(&err);
  int rc = cable_session_loadbd(self->s, name, &list, &n, &err);
  return rc ? pyc_raise(rc, &err) : pyc_branch_list(list, n);
}

/* transform(branches, relabel) -> [Branch, ...]: AUTO's merge or relabel */
static PyObject *session_transform(PyObject *obj, PyObject *args)
{
  pyc_session *self = (pyc_session *)obj;
  PyObject *seq;
  int relabel;
  if (!PyArg_ParseTuple(args, "Op", &seq, &relabel)) return NULL;
  cable_branch **br, **list = NULL;
  int n, nout = 0;
  if (pyc_branches_from(seq, &br, &n) < 0) return NULL;
  cable_error err;
  cable_error_clear(&err);
  int rc = cable_session_transform(self->s, br, n, relabel, &list, &nout, &err);
  PyMem_Free(br);
  return rc ? pyc_raise(rc, &err) : pyc_branch_list(list, nout);
}

/* transform_files(name, relabel): merge or relabel b./s./d.NAME in place */
static PyObject *session_transform_files(PyObject *obj, PyObject *args)
{
  pyc_session *self = (pyc_session *)obj;
  const char *name;
  int relabel;
  if (!PyArg_ParseTuple(args, "sp", &name, &relabel)) return NULL;
  cable_error err;
  cable_error_clear(&err);
  int rc = cable_session_transform_files(self->s, name, relabel, &err);
  if (rc) return pyc_raise(rc, &err);
  Py_RETURN_NONE;
}

/* constants() -> dict: the runner's constants (AUTO's pr()), what the next
 * run without a start and without c= uses */
static PyObject *session_constants(PyObject *obj, PyObject *noargs)
{
  (void)noargs;
  const cable_constants *c;
  const cable_names *names;
  const char *e;
  cable_error err;
  cable_error_clear(&err);
  int rc = cable_session_constants(((pyc_session *)obj)->s, &c, &names, &e, &err);
  return rc ? pyc_raise(rc, &err) : pyc_constants_dict(c, names, e);
}

/* info(e) -> str: the problem's parameters, components, keys and
 * recommended constants (cable_session_info, `cable info e=NAME`) */
static PyObject *session_info(PyObject *obj, PyObject *args)
{
  const char *e;
  if (!PyArg_ParseTuple(args, "s", &e)) return NULL;
  char *text = NULL;
  size_t len = 0;
  FILE *f = open_memstream(&text, &len);
  if (!f) return PyErr_NoMemory();
  cable_error err;
  cable_error_clear(&err);
  int rc = cable_session_info(((pyc_session *)obj)->s, e, f, &err);
  fclose(f);
  PyObject *out = rc ? pyc_raise(rc, &err) : PyUnicode_FromStringAndSize(text, (Py_ssize_t)len);
  free(text);
  return out;
}

static PyMethodDef session_methods[] = {
    {"info", session_info, METH_VARARGS, "info(e) -> str: the problem's parameters, components, keys, recommended constants"},
    {"run", session_run, METH_VARARGS, "run(start, sol, name, e, c, s, sv, ap, overrides) -> Branch"},
    {"load", session_load, METH_VARARGS, "load(start, sol, name, e, c, s, sv, ap, overrides) -> Branch or None (no solution)"},
    {"save", session_save, METH_VARARGS, "save(branches, sol, name, append)"},
    {"loadbd", session_loadbd, METH_VARARGS, "loadbd(name) -> [Branch, ...]"},
    {"transform", session_transform, METH_VARARGS, "transform(branches, relabel) -> [Branch, ...]"},
    {"transform_files", session_transform_files, METH_VARARGS, "transform_files(name, relabel)"},
    {"constants", session_constants, METH_NOARGS, "constants() -> dict: the runner's constants (AUTO's pr())"},
    {NULL, NULL, 0, NULL}};

PyTypeObject pyc_session_type = {
    PyVarObject_HEAD_INIT(NULL, 0).tp_name = "cable._cable.Session",
    .tp_basicsize = sizeof(pyc_session),
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "AUTO's runner on cable's engine: constants and problem of the last run, label numbering",
    .tp_new = PyType_GenericNew,
    .tp_init = session_init,
    .tp_dealloc = session_dealloc,
    .tp_methods = session_methods,
};
