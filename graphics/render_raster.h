/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The renderer's z-buffer: shaded triangles and flat-coloured wide line
 * segments, depth-tested per sample. */
#ifndef CABLE_RENDER_RASTER_H
#define CABLE_RENDER_RASTER_H

typedef struct {
  int w, h;              /* samples */
  float *depth;          /* [w h]; +inf where nothing was drawn */
  unsigned char *rgb;    /* [3 w h] */
} render_zbuf;

/* A triangle corner: sample coordinates (x right, y down, sample centres at
 * half-integers), depth (larger is farther), unit normal in camera
 * coordinates (right, up, view) and base colour. */
typedef struct {
  double x, y, z;
  double n[3];
  double rgb[3];
} render_vertex;

render_zbuf *render_zbuf_alloc(int w, int h);
void render_zbuf_free(render_zbuf *zb);
void render_zbuf_clear(render_zbuf *zb, const double rgb[3]);
/* Lambert + Blinn-Phong shading with a fixed light from the upper left
 * front; normals facing away from the viewer are flipped (two-sided). */
void render_zbuf_triangle(render_zbuf *zb, const render_vertex *a, const render_vertex *b,
                          const render_vertex *c);
/* Segment from (x0, y0, z0) to (x1, y1, z1) of the given width (samples)
 * with round ends, flat colour, drawn where it is in front of what the
 * buffer holds.  An overlay (overlay != 0) does not update the depth: of
 * several overlays over the same surface the last one drawn shows, so
 * outlines and overlapping profiles never fight over nearly equal depths. */
void render_zbuf_segment(render_zbuf *zb, const double p0[3], const double p1[3], double width,
                         const double rgb[3], int overlay);
/* Shaded colour of base colour rgb for camera-space unit normal n. */
void render_shade(const double n[3], const double rgb[3], double out[3]);

#endif
