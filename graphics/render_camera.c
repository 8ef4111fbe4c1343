/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The renderer's view: default direction from the point cloud's shape, and
 * a fit of the drawn tubes to the picture. */
#include <math.h>

#include <gsl/gsl_eigen.h>
#include <gsl/gsl_matrix.h>

#include "cable/cable_status.h"
#include "graphics_vec.h"
#include "render.h"
#include "render_colormap.h"

/* Empty border around the drawn tubes, as a fraction of the picture. */
#define RENDER_MARGIN 0.04
/* An up vector within this sine of the view direction does not define the
 * picture's orientation; the default is used instead. */
#define RENDER_UP_MIN_SINE 1e-6
/* Looking within acos(0.9) = 26 degrees of world z, world z cannot be "up";
 * world y is used. */
#define RENDER_UP_Z_LIMIT 0.9
/* Fixed-point passes for automatic thickening (the drawn radius changes the
 * fit, which changes the radius in pixels): the change per pass is of order
 * radius / extent, below a pixel after the second pass. */
#define RENDER_FIT_PASSES 3

/* Direction of least extent of all centreline points (smallest eigenvalue of
 * their covariance), its largest component made negative so that a curve in
 * the xy plane is seen from +z. */
static int render_default_view(const render_tube *tubes, int ntube, double view[3])
{
  double mean[3] = {0, 0, 0}, cov[9] = {0};
  long count = 0;
  for (int k = 0; k < ntube; k++)
    for (int i = 0; i < tubes[k].n; i++, count++)
      for (int a = 0; a < 3; a++) mean[a] += tubes[k].xyz[3 * i + a];
  for (int a = 0; a < 3; a++) mean[a] /= (double)count;
  for (int k = 0; k < ntube; k++)
    for (int i = 0; i < tubes[k].n; i++)
      for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++)
          cov[3 * a + b] += (tubes[k].xyz[3 * i + a] - mean[a]) * (tubes[k].xyz[3 * i + b] - mean[b]);
  gsl_matrix_view m = gsl_matrix_view_array(cov, 3, 3);
  gsl_vector *eval = gsl_vector_alloc(3);
  gsl_matrix *evec = gsl_matrix_alloc(3, 3);
  gsl_eigen_symmv_workspace *w = gsl_eigen_symmv_alloc(3);
  int st = CABLE_ERR_ALLOC;
  if (eval && evec && w && gsl_eigen_symmv(&m.matrix, eval, evec, w) == 0) {
    gsl_eigen_symmv_sort(eval, evec, GSL_EIGEN_SORT_VAL_ASC);
    int big = 0;
    for (int a = 0; a < 3; a++) {
      view[a] = gsl_matrix_get(evec, a, 0);
      if (fabs(view[a]) > fabs(view[big])) big = a;
    }
    if (view[big] > 0)
      for (int a = 0; a < 3; a++) view[a] = -view[a];
    st = cable_vec3_normalize(view) > 0 ? CABLE_SUCCESS : CABLE_ERR_INPUT;
  }
  gsl_eigen_symmv_free(w);
  gsl_matrix_free(evec);
  gsl_vector_free(eval);
  return st;
}

static int render_basis(const render_tube *tubes, int ntube, const cable_render_options *opt,
                        render_camera *cam)
{
  double *v = cam->view, *u = cam->up;
  for (int a = 0; a < 3; a++) v[a] = opt ? opt->view_dir[a] : 0.0;
  if (!isfinite(cable_vec3_norm(v))) return CABLE_ERR_INPUT;
  if (cable_vec3_normalize(v) == 0) {
    int st = render_default_view(tubes, ntube, v);
    if (st != CABLE_SUCCESS) return st;
  }
  for (int a = 0; a < 3; a++) u[a] = opt ? opt->up[a] : 0.0;
  if (!isfinite(cable_vec3_norm(u))) return CABLE_ERR_INPUT;
  cable_vec3_axpy(u, -cable_vec3_dot(u, v), v, u);
  if (cable_vec3_norm(u) <= RENDER_UP_MIN_SINE * (opt ? cable_vec3_norm(opt->up) : 0.0) ||
      cable_vec3_normalize(u) == 0) {
    double z = fabs(v[2]) < RENDER_UP_Z_LIMIT ? 1.0 : 0.0;
    u[0] = 0, u[1] = 1.0 - z, u[2] = z;
    cable_vec3_axpy(u, -cable_vec3_dot(u, v), v, u);
    cable_vec3_normalize(u);
  }
  cable_vec3_cross(v, u, cam->right);
  return CABLE_SUCCESS;
}

int render_camera_fit(const render_tube *tubes, int ntube, const cable_render_options *opt,
                      render_camera *cam)
{
  if (tubes == NULL || ntube < 1 || cam == NULL) return CABLE_ERR_INPUT;
  cam->width = opt && opt->width > 0 ? opt->width : RENDER_DEFAULT_SIZE;
  cam->height = opt && opt->height > 0 ? opt->height : RENDER_DEFAULT_SIZE;
  if (cam->width > RENDER_MAX_SIZE || cam->height > RENDER_MAX_SIZE) return CABLE_ERR_INPUT;
  int has_scalar = 0;
  double rmin = INFINITY, rmax = 0;
  for (int k = 0; k < ntube; k++) {
    if (tubes[k].n < 2 || tubes[k].xyz == NULL || !(tubes[k].radius > 0) ||
        !isfinite(tubes[k].radius))
      return CABLE_ERR_INPUT;
    for (int i = 0; i < 3 * tubes[k].n; i++)
      if (!isfinite(tubes[k].xyz[i])) return CABLE_ERR_INPUT;
    has_scalar |= tubes[k].scalar != NULL;
    rmin = fmin(rmin, tubes[k].radius);
    rmax = fmax(rmax, tubes[k].radius);
  }
  int st = render_basis(tubes, ntube, opt, cam);
  if (st != CABLE_SUCCESS) return st;

  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (int k = 0; k < ntube; k++)
    for (int i = 0; i < tubes[k].n; i++) {
      const double *p = tubes[k].xyz + 3 * i;
      double x = cable_vec3_dot(p, cam->right), y = cable_vec3_dot(p, cam->up);
      lo[0] = fmin(lo[0], x), hi[0] = fmax(hi[0], x);
      lo[1] = fmin(lo[1], y), hi[1] = fmax(hi[1], y);
    }
  double cx = 0.5 * (lo[0] + hi[0]), cy = 0.5 * (lo[1] + hi[1]);
  for (int a = 0; a < 3; a++) cam->centre[a] = cx * cam->right[a] + cy * cam->up[a];

  int bar = opt && opt->colormap != CABLE_RENDER_COLORMAP_NONE && has_scalar;
  cam->plot_width = cam->width - (bar ? render_colorbar_width(cam->width, cam->height) : 0);
  double aw = cam->plot_width - 2.0 * RENDER_MARGIN * cam->width;
  double ah = cam->height * (1.0 - 2.0 * RENDER_MARGIN);
  if (aw < 1 || ah < 1) return CABLE_ERR_INPUT;
  int automatic = !(opt && opt->thicken > 0);
  cam->thicken = automatic ? 1.0 : opt->thicken;
  for (int pass = 0; pass < (automatic ? RENDER_FIT_PASSES : 1); pass++) {
    double d = 2.0 * rmax * cam->thicken;
    cam->scale = fmin(aw / (hi[0] - lo[0] + d), ah / (hi[1] - lo[1] + d));
    if (automatic) cam->thicken = fmax(1.0, RENDER_MIN_RADIUS_PX / (rmin * cam->scale));
  }
  if (!isfinite(cam->scale) || !(cam->scale > 0)) return CABLE_ERR_INPUT;
  cam->cx = 0.5 * cam->plot_width;
  cam->cy = 0.5 * cam->height;
  return CABLE_SUCCESS;
}

void render_camera_project(const render_camera *cam, const double p[3], double *x, double *y,
                           double *depth)
{
  double d[3];
  cable_vec3_sub(p, cam->centre, d);
  *x = cam->cx + cam->scale * cable_vec3_dot(d, cam->right);
  *y = cam->cy - cam->scale * cable_vec3_dot(d, cam->up);
  *depth = cable_vec3_dot(d, cam->view);
}
