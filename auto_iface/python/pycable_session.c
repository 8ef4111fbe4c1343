/* SPDX-License-Identifier: GPL-3.0-or-later */
/* cable._cable.Session: AUTO's runner on cable's engine (cable_session.h).
 * Runs release the GIL; after every computed point the session takes it back
 * for a moment to run Python's signal handlers, so Ctrl-C (KeyboardInterrupt)
 * stops a run after the point being computed: its files (sv=) hold every
 * point before, the exception says where and carries the partial branch.
 *
 * Threads: the C session is one runner's state (AUTO's), not safe to use from
 * two threads at once, and a run releases the GIL.  So every method takes the
 * session's lock: a second thread calling run() (or any other method) on a
 * runner that is running waits until the first call returns, then runs; a
 * call from the running thread itself (a signal handler during the run) is
 * refused with RuntimeError.  Separate runners run at the same time. */
#include "pycable.h"

#include <stdio.h>
#include <stdlib.h>

typedef struct pyc_session {
  PyObject_HEAD
  cable_session *s;
  PyThreadState *ts;          /* the running thread's state while a run has released the GIL */
  PyThread_type_lock lock;    /* held by the call in progress */
  int busy;                   /* a call is in progress (read and written with the GIL held) */
  unsigned long owner;        /* ... in this thread */
  FILE *log;                  /* the session's log, written to sys.stdout (log_write) */
} pyc_session;

/* How long a waiting call sleeps between looks at Python's signal handlers
 * (Ctrl-C while waiting for another thread's run), in microseconds. */
#define SESSION_WAIT_US 100000

/* Take the session for one call (with the GIL): waits, with the GIL released,
 * while another thread's call is in progress.  0, or -1 with an exception. */
static int session_enter(pyc_session *self)
{
  unsigned long me = PyThread_get_thread_ident();
  if (!self->s || !self->lock) {
    PyErr_SetString(PyExc_RuntimeError, "cable: the runner's session is not initialised (Session.__init__ not called)");
    return -1;
  }
  if (self->busy && self->owner == me) {
    PyErr_SetString(PyExc_RuntimeError,
                    "cable: this runner is already running a command in this thread (a call from a signal handler "
                    "during run()?); use another Runner");
    return -1;
  }
  while (!PyThread_acquire_lock(self->lock, NOWAIT_LOCK)) {
    PyLockStatus got;
    Py_BEGIN_ALLOW_THREADS
    got = PyThread_acquire_lock_timed(self->lock, SESSION_WAIT_US, 0);
    Py_END_ALLOW_THREADS
    if (got == PY_LOCK_ACQUIRED) break;
    if (PyErr_CheckSignals() < 0) return -1;
  }
  self->busy = 1;
  self->owner = me;
  return 0;
}

static void session_leave(pyc_session *self)
{
  self->busy = 0;
  self->owner = 0;
  PyThread_release_lock(self->lock);
}

/* The session's log lines go to Python's sys.stdout as they are printed,
 * flushed: in order with the script's own prints, through a pipe, and in a
 * notebook (whose cells show sys.stdout, not the process's stdout).  Called
 * with or without the GIL (a run releases it). */
static ssize_t log_write(void *cookie, const char *buf, size_t n)
{
  (void)cookie;
  PyGILState_STATE g = PyGILState_Ensure();
  PyObject *t, *v, *tb;
  PyErr_Fetch(&t, &v, &tb);   /* a pending exception (KeyboardInterrupt) stays */
  PyObject *out = PySys_GetObject("stdout");   /* borrowed */
  PyObject *text = PyUnicode_DecodeUTF8(buf, (Py_ssize_t)n, "replace");
  if (out && out != Py_None && text) {
    PyObject *r = PyObject_CallMethod(out, "write", "O", text);
    Py_XDECREF(r);
    r = PyObject_CallMethod(out, "flush", NULL);
    Py_XDECREF(r);
  } else if (text) {
    fwrite(buf, 1, n, stdout);   /* no sys.stdout (an embedding without one) */
    fflush(stdout);
  }
  Py_XDECREF(text);
  PyErr_Clear();
  PyErr_Restore(t, v, tb);
  PyGILState_Release(g);
  return (ssize_t)n;
}

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
  if (!self->lock && !(self->lock = PyThread_allocate_lock())) {
    PyErr_NoMemory();
    return -1;
  }
  cable_session_options o;
  cable_session_options_init(&o);
  o.dir = NULL;   /* the current directory: the Python layer changes it (AUTO's cd) */
  o.interrupt = session_interrupt;
  o.interrupt_ctx = self;
  cookie_io_functions_t io = {NULL, log_write, NULL, NULL};
  self->log = fopencookie(NULL, "w", io);
  if (self->log) setvbuf(self->log, NULL, _IOLBF, 0);   /* a line at a time */
  o.log = self->log;
  self->s = cable_session_alloc(&o);
  if (!self->s) {
    PyErr_NoMemory();
    return -1;
  }
  return 0;
}

static void session_dealloc(PyObject *obj)
{
  pyc_session *self = (pyc_session *)obj;
  cable_session_free(self->s);
  if (self->lock) PyThread_free_lock(self->lock);
  if (self->log) fclose(self->log);
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

/* (start, sol, mbr, mlab, name, e, c, s, sv, ap, over[, keep_state]): start a Branch with
 * sol >= 0 (a solution, mbr and mlab the largest branch number and label of
 * the result it was taken from), a list of branches (a result), or None;
 * name, e, c, s, sv, ap str or None; over a list of "KEY=VALUE" statements. */
static int inputs_parse(PyObject *args, run_inputs *in)
{
  memset(in, 0, sizeof *in);
  PyObject *start, *name, *e, *c, *s, *sv, *ap, *over;
  int sol, mbr, mlab, keep = 0;
  if (!PyArg_ParseTuple(args, "OiiiOOOOOOO|p", &start, &sol, &mbr, &mlab, &name, &e, &c, &s, &sv, &ap, &over, &keep))
    return -1;
  in->a.keep_state = keep;
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

/* A KeyboardInterrupt (or another exception a signal handler raised) that
 * stopped a run: it gets the run's message as a note (where the points are)
 * and the partial branch as its attribute branch. */
static PyObject *interrupted(cable_branch *b, const cable_error *err)
{
  PyObject *t, *v, *tb;
  PyErr_Fetch(&t, &v, &tb);
  PyErr_NormalizeException(&t, &v, &tb);
  if (v) {
    char buf[1400];
    PyObject *r = PyObject_CallMethod(v, "add_note", "s", cable_error_format(err, buf, sizeof buf));
    Py_XDECREF(r);
    PyObject *w = b ? pyc_branch_wrap(b) : NULL;
    b = NULL;
    if (w) PyObject_SetAttrString(v, "branch", w);
    Py_XDECREF(w);
    PyErr_Clear();   /* a failure above leaves the interrupt as it was */
    if (tb) PyException_SetTraceback(v, tb);
  }
  cable_branch_decref(b);
  PyErr_Restore(t, v, tb);
  return NULL;
}

/* The opening of run() and load(): the arguments parsed into in and the
 * session entered; -1 with the Python error set (in freed) otherwise. */
static int inputs_open(pyc_session *self, PyObject *args, run_inputs *in)
{
  if (inputs_parse(args, in) < 0 || session_enter(self) < 0) {
    inputs_free(in);
    return -1;
  }
  return 0;
}

/* run(start, sol, mbr, mlab, name, e, c, s, sv, ap, over) -> Branch */
static PyObject *session_run(PyObject *obj, PyObject *args)
{
  pyc_session *self = (pyc_session *)obj;
  run_inputs in;
  if (inputs_open(self, args, &in) < 0) return NULL;
  cable_branch *b = NULL;
  cable_error err;
  cable_error_clear(&err);
  fflush(stdout);
  self->ts = PyEval_SaveThread();
  int rc = cable_session_run(self->s, &in.a, &b, &err);
  PyEval_RestoreThread(self->ts);
  self->ts = NULL;
  session_leave(self);
  fflush(stdout);
  inputs_free(&in);
  if (rc == CABLE_ERR_INTERRUPTED && PyErr_Occurred()) return interrupted(b, &err);
  return rc ? pyc_raise(rc, &err) : pyc_branch_wrap(b);
}

/* load(start, sol, mbr, mlab, name, e, c, s, sv, ap, over) -> Branch with one solution */
static PyObject *session_load(PyObject *obj, PyObject *args)
{
  pyc_session *self = (pyc_session *)obj;
  run_inputs in;
  if (inputs_open(self, args, &in) < 0) return NULL;
  cable_branch *b = NULL;
  cable_error err;
  cable_error_clear(&err);
  int rc = cable_session_load(self->s, &in.a, &b, &err);
  session_leave(self);
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
  if (session_enter(self) < 0) {
    PyMem_Free(br);
    return NULL;
  }
  cable_error err;
  cable_error_clear(&err);
  fflush(stdout);
  int rc = cable_session_save(self->s, br, n, sol, name, append, &err);
  session_leave(self);
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
  if (session_enter(self) < 0) return NULL;
  cable_error err;
  cable_error_clear(&err);
  int rc = cable_session_loadbd(self->s, name, &list, &n, &err);
  session_leave(self);
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
  if (session_enter(self) < 0) {
    PyMem_Free(br);
    return NULL;
  }
  cable_error err;
  cable_error_clear(&err);
  int rc = cable_session_transform(self->s, br, n, relabel, &list, &nout, &err);
  session_leave(self);
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
  if (session_enter(self) < 0) return NULL;
  cable_error err;
  cable_error_clear(&err);
  int rc = cable_session_transform_files(self->s, name, relabel, &err);
  session_leave(self);
  if (rc) return pyc_raise(rc, &err);
  Py_RETURN_NONE;
}

/* constants() -> dict: the runner's constants (AUTO's pr()), what the next
 * run without a start and without c= uses */
static PyObject *session_constants(PyObject *obj, PyObject *noargs)
{
  (void)noargs;
  pyc_session *self = (pyc_session *)obj;
  const cable_constants *c;
  const cable_names *names;
  const char *e;
  cable_error err;
  cable_error_clear(&err);
  if (session_enter(self) < 0) return NULL;
  int rc = cable_session_constants(self->s, &c, &names, &e, &err);
  PyObject *d = rc ? pyc_raise(rc, &err) : pyc_constants_dict(c, names, e);
  session_leave(self);
  return d;
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

/* add_known(branch, sol) -> int: the branch points of branch (sol < 0:
 * every one; else that solution) become known points of later runs
 * (cable_session_add_known); the number added */
static PyObject *session_add_known(PyObject *obj, PyObject *args)
{
  pyc_session *self = (pyc_session *)obj;
  PyObject *b;
  int sol;
  if (!PyArg_ParseTuple(args, "O!i", &pyc_branch_type, &b, &sol)) return NULL;
  if (session_enter(self) < 0) return NULL;
  cable_error err;
  cable_error_clear(&err);
  int rc = cable_session_add_known(self->s, ((pyc_branch *)b)->b, sol, &err);
  session_leave(self);
  return rc < 0 ? pyc_raise(rc, &err) : PyLong_FromLong(rc);
}

/* clear_known(): forgets the known points; nknown() -> int */
static PyObject *session_clear_known(PyObject *obj, PyObject *noargs)
{
  (void)noargs;
  pyc_session *self = (pyc_session *)obj;
  if (session_enter(self) < 0) return NULL;
  cable_session_clear_known(self->s);
  session_leave(self);
  Py_RETURN_NONE;
}

static PyObject *session_nknown(PyObject *obj, PyObject *noargs)
{
  (void)noargs;
  return PyLong_FromLong(cable_session_nknown(((pyc_session *)obj)->s));
}

static PyMethodDef session_methods[] = {
    {"info", session_info, METH_VARARGS, "info(e) -> str: the problem's parameters, components, keys, recommended constants"},
    {"run", session_run, METH_VARARGS,
     "run(start, sol, name, e, c, s, sv, ap, overrides[, keep_state]) -> Branch (keep_state: a probe that leaves "
     "the runner's state as it was)"},
    {"load", session_load, METH_VARARGS, "load(start, sol, name, e, c, s, sv, ap, overrides) -> Branch or None (no solution)"},
    {"save", session_save, METH_VARARGS, "save(branches, sol, name, append)"},
    {"loadbd", session_loadbd, METH_VARARGS, "loadbd(name) -> [Branch, ...]"},
    {"transform", session_transform, METH_VARARGS, "transform(branches, relabel) -> [Branch, ...]"},
    {"transform_files", session_transform_files, METH_VARARGS, "transform_files(name, relabel)"},
    {"add_known", session_add_known, METH_VARARGS, "add_known(branch, sol) -> int: its BPs (sol < 0: all) become known points"},
    {"clear_known", session_clear_known, METH_NOARGS, "clear_known(): forget the known points"},
    {"nknown", session_nknown, METH_NOARGS, "nknown() -> int: the number of known points"},
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
