/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Tube meshes for other programs: VTK XML PolyData (.vtp, ParaView) and
 * Stanford PLY (.ply, Blender, MeshLab), both ASCII.  The input is the
 * renderer's (render_tube); the mesh is the one the renderer draws
 * (tube_mesh.h: rotation-minimising rings, flat caps on open tubes) at the
 * true radius. */
#ifndef CABLE_EXPORT_H
#define CABLE_EXPORT_H

#include "render.h"

typedef struct {
  int nsides;               /* vertices per ring; 0 -> EXPORT_NSIDES_DEFAULT */
  const char *scalar_name;  /* .vtp point-data name of the scalar; NULL ->
                               "pressure"; letters, digits, '_' and '-' only */
} export_options;

/* 16 sides keep the facets' deviation from the circle below 2 % of the
 * radius (1 - cos(pi/16) = 0.019) at a modest file size. */
#define EXPORT_NSIDES_DEFAULT 16

/* One .vtp file with
 *   Polys  the triangles of every tube (tube order);
 *   Lines  every tube's centreline (closed ones end on their first point
 *          again), then every curve in `curves` (e.g. the contact curve;
 *          only xyz, value and n are used);
 *   Points the tube vertices, then the centreline points, then the curve
 *          points;
 *   PointData  the scalar (tube scalar, 0 for tubes without one; the curve's
 *          value), "part" (tube k -> k, curve j -> ntube + j) and "Normals"
 *          (surface normals; zero on line points).
 * curves may be NULL when ncurve == 0; opt NULL means defaults.  Returns
 * CABLE_SUCCESS, CABLE_ERR_INPUT (as render_tubes_png, and a bad option),
 * CABLE_ERR_IO or CABLE_ERR_ALLOC.  Written atomically. */
int export_vtp_write(const render_tube *tubes, int ntube, const render_profile *curves,
                     int ncurve, const export_options *opt, const char *path);

/* One .ply file with the tube triangles: per vertex x y z, nx ny nz, the
 * tube colour (red green blue, 0-255) and the scalar as "quality" (MeshLab
 * colours by it; 0 for tubes without a scalar).  Same returns. */
int export_ply_write(const render_tube *tubes, int ntube, const export_options *opt,
                     const char *path);

#endif
