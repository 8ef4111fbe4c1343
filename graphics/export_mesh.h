/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Shared by the exporters: input checks and the meshes of all tubes. */
#ifndef CABLE_EXPORT_MESH_H
#define CABLE_EXPORT_MESH_H

#include <stdio.h>

#include "atomic_file.h"
#include "export.h"
#include "tube_mesh.h"

/* An export being written: the meshes of all tubes and the destination,
 * open as a temporary file until export_end. */
typedef struct {
  tube_mesh **m;           /* m[ntube], owned */
  int ntube;
  cable_atomic_file *file; /* owned until export_end */
  FILE *f;                 /* file's stream */
} export_out;

/* The preamble every exporter shares: checks the input (export_check),
 * meshes every tube and opens path atomically.  CABLE_SUCCESS (then call
 * export_end), or CABLE_ERR_INPUT, CABLE_ERR_ALLOC, CABLE_ERR_IO with
 * nothing left allocated and nothing written. */
int export_begin(const render_tube *tubes, int ntube, const render_profile *curves, int ncurve,
                 const export_options *opt, const char *path, export_out *out);
/* Frees the meshes and renames the file over path: CABLE_SUCCESS or
 * CABLE_ERR_IO (the destination untouched). */
int export_end(export_out *out);

/* Checks tubes (as the renderer does), curves and options; fills the ring
 * size.  CABLE_SUCCESS or CABLE_ERR_INPUT. */
int export_check(const render_tube *tubes, int ntube, const render_profile *curves, int ncurve,
                 const export_options *opt, const char *path, int *nsides);
/* Mesh every tube at its true radius into m[ntube]; on failure nothing is
 * left allocated.  CABLE_SUCCESS, CABLE_ERR_INPUT or CABLE_ERR_ALLOC. */
int export_meshes_build(const render_tube *tubes, int ntube, int nsides, tube_mesh **m);
void export_meshes_free(tube_mesh **m, int ntube);

#endif
