/* Shared by the exporters: input checks and the meshes of all tubes. */
#ifndef CABLE_EXPORT_MESH_H
#define CABLE_EXPORT_MESH_H

#include "export.h"
#include "tube_mesh.h"

/* Checks tubes (as the renderer does), curves and options; fills the ring
 * size.  CABLE_SUCCESS or CABLE_ERR_INPUT. */
int export_check(const render_tube *tubes, int ntube, const render_profile *curves, int ncurve,
                 const export_options *opt, const char *path, int *nsides);
/* Mesh every tube at its true radius into m[ntube]; on failure nothing is
 * left allocated.  CABLE_SUCCESS, CABLE_ERR_INPUT or CABLE_ERR_ALLOC. */
int export_meshes_build(const render_tube *tubes, int ntube, int nsides, tube_mesh **m);
void export_meshes_free(tube_mesh **m, int ntube);

#endif
