/* SPDX-License-Identifier: GPL-3.0-or-later */
/* libcable: elastic cable knots and links by numerical continuation.
 * The whole public API (doc/api.md); a program or plug-in includes this
 * header, or the single headers below, and links with
 * `pkg-config --cflags --libs cable`. */
#ifndef CABLE_H
#define CABLE_H

#include "cable/cable_api.h"
#include "cable/cable_status.h"       /* status codes and their messages */
#include "cable/cable_error.h"        /* file:line:key error reports */
#include "cable/cable_problem.h"      /* the problem interface, built-in problems */
#include "cable/cable_names.h"        /* parameter, component and point-type names */
#include "cable/cable_constants.h"    /* AUTO constants and constants files */
#include "cable/cable_solution.h"     /* stored solutions */
#include "cable/cable_output.h"       /* what the engine hands out: points, sinks */
#include "cable/cable_cont.h"         /* the continuation handle and driver */
#include "cable/cable_stability.h"    /* the Morse index of a variational problem's solution */
#include "cable/cable_fold.h"         /* fold continuation (ISW = 2): the extended problem */
#include "cable/cable_bpcont.h"       /* branch-point continuation (ISW = 2 at a BP): the extended problem */
#include "cable/cable_aufile.h"       /* b./s./d. files: writer and readers */
#include "cable/cable_plugin.h"       /* problems from shared objects */
#include "cable/cable_autoeq.h"       /* AUTO equation files (NAME.f90, NAME.f, NAME.c) */
#include "cable/cable_analysis.h"     /* analysis of braid solutions */
#include "cable/cable_graphics.h"     /* the option types of the pictures */
#include "cable/cable_pictures.h"     /* bifurcation diagrams and 3-D pictures */
#include "cable/cable_session.h"      /* AUTO's runner: runs, results, files (the Python package) */
#include "cable/cable_version.h"

#endif
