/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Triangle meshes of tubes around space curves, built on rotation-minimising
 * frames (parallel transport by the double-reflection method of Wang,
 * Juettler, Zheng and Liu, ACM TOG 27, 2008).  For closed curves the twist
 * that transport accumulates around the loop is spread evenly over the
 * arclength, so the mesh closes smoothly.  Shared by the renderer and the
 * VTK/PLY exports. */
#ifndef CABLE_TUBE_MESH_H
#define CABLE_TUBE_MESH_H

/* A closed curve given with its first point repeated at the end (as a
 * closed solution's last mesh point is) has a closing segment shorter than
 * this fraction of the mean segment: the repeat is dropped.  Any real mesh
 * interval is many orders longer; boundary-condition residuals are far
 * shorter. */
#define TUBE_DUPLICATE_REL 1e-6
#define TUBE_NSIDES_MIN 3
#define TUBE_NSIDES_MAX 256

/* Number of distinct centreline points: n, or n - 1 when the curve is closed
 * and its last point repeats the first.  n < 2 or NULL xyz gives 0. */
int tube_points_count(int n, const double *xyz, int closed);

/* Unit tangents t[3n] (normalised sum of the unit chords either side) and
 * rotation-minimising unit normals nrm[3n] (nrm . t = 0).  closure (may be
 * NULL) receives, for closed curves, the angle by which plain transport
 * around the loop missed the starting normal (0 for open curves); this angle
 * has been removed linearly in arclength.  Returns CABLE_SUCCESS or
 * CABLE_ERR_INPUT (n < 2, NULL, non-finite or all points coincident). */
int tube_frames_compute(int n, const double *xyz, int closed, double *t, double *nrm,
                        double *closure);

typedef struct {
  int npts;        /* centreline points (already without a repeated end) */
  int nsides;      /* vertices per ring */
  int closed;
  int nv, ntri;    /* vertex and triangle counts (tube_mesh_counts) */
  double *xyz;     /* [3 nv] vertex positions */
  double *normal;  /* [3 nv] outward unit normals */
  double *scalar;  /* [nv] the centreline scalar at each vertex (0 without one) */
  int *tri;        /* [3 ntri] counter-clockwise seen from outside */
  double *t, *nrm; /* [3 npts] frames of the last build */
} tube_mesh;

/* Vertex and triangle counts.  Ring i, side j is vertex i * nsides + j.
 * Closed: nv = npts * nsides, ntri = 2 * npts * nsides.  Open: each end
 * gets a flat cap (a centre vertex and a copy of the end ring with the axial
 * normal): nv = npts * nsides + 2 (nsides + 1),
 * ntri = 2 (npts - 1) nsides + 2 nsides. */
void tube_mesh_counts(int npts, int nsides, int closed, int *nv, int *ntri);
/* NULL when npts < 2, nsides outside [TUBE_NSIDES_MIN, TUBE_NSIDES_MAX] or
 * out of memory. */
tube_mesh *tube_mesh_alloc(int npts, int nsides, int closed);
/* Mesh the tube of the given radius around the first npts points of xyz
 * (scalar [npts] or NULL).  CABLE_SUCCESS or CABLE_ERR_INPUT. */
int tube_mesh_build(tube_mesh *m, const double *xyz, const double *scalar, double radius);
void tube_mesh_free(tube_mesh *m);

#endif
