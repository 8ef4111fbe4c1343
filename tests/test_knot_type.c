/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Knot identification (knot_type.h) on exact curves: torus knots of both
 * handednesses, the figure-eight, unknots with many crossings, random
 * rotations, and the error paths.  All checks are exact (integers). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_math.h>
#include <gsl/gsl_rng.h>

#include "cable/cable_status.h"
#include "harness.h"
#include "knot_type.h"

/* Torus knot T(p,q) on the torus (R, a) = (2, 1); hand = +1 right-handed
 * (the push-off along the torus normal links it +pq times, test_ribbon). */
static void torus_curve(int p, int q, double hand, int n, double *xyz)
{
  for (int i = 0; i < n; i++) {
    double u = 2 * M_PI * i / n, rho = 2.0 + cos(q * u);
    xyz[3 * i] = rho * cos(p * u);
    xyz[3 * i + 1] = rho * sin(p * u);
    xyz[3 * i + 2] = -hand * sin(q * u);
  }
}

/* A standard figure-eight parametrisation (Lissajous-type torus curve). */
static void figure_eight(int n, double *xyz)
{
  for (int i = 0; i < n; i++) {
    double u = 2 * M_PI * i / n;
    xyz[3 * i] = (2 + cos(2 * u)) * cos(3 * u);
    xyz[3 * i + 1] = (2 + cos(2 * u)) * sin(3 * u);
    xyz[3 * i + 2] = sin(4 * u);
  }
}

/* Star-shaped about the z axis in projection along z, hence an unknot, but
 * with large vertical oscillations: side views have many crossings. */
static void wobbly_circle(int n, double *xyz)
{
  for (int i = 0; i < n; i++) {
    double u = 2 * M_PI * i / n, rho = 1.0 + 0.3 * cos(7 * u);
    xyz[3 * i] = rho * cos(u);
    xyz[3 * i + 1] = rho * sin(u);
    xyz[3 * i + 2] = 2.0 * sin(5 * u) + cos(9 * u);
  }
}

/* Uniform random rotation from a random unit quaternion. */
static void random_rotate(gsl_rng *rng, int n, double *xyz)
{
  double q[4], nn = 0;
  for (int i = 0; i < 4; i++) {
    q[i] = gsl_rng_uniform(rng) - 0.5;
    nn += q[i] * q[i];
  }
  nn = sqrt(nn);
  for (int i = 0; i < 4; i++) q[i] /= nn;
  double a = q[0], b = q[1], c = q[2], d = q[3];
  double R[9] = {a * a + b * b - c * c - d * d, 2 * (b * c - a * d), 2 * (b * d + a * c),
                 2 * (b * c + a * d), a * a - b * b + c * c - d * d, 2 * (c * d - a * b),
                 2 * (b * d - a * c), 2 * (c * d + a * b), a * a - b * b - c * c + d * d};
  for (int i = 0; i < n; i++) {
    double x[3] = {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
    for (int k = 0; k < 3; k++) xyz[3 * i + k] = R[3 * k] * x[0] + R[3 * k + 1] * x[1] + R[3 * k + 2] * x[2];
  }
}

static int poly_is(const cable_knot_type_result *r, const long *c, int deg)
{
  if (r->alex_degree != deg) return 0;
  for (int i = 0; i <= deg; i++)
    if (r->alex[i] != c[i]) return 0;
  return 1;
}

typedef struct {
  int p, q;
  const char *name;
  int crossings, det, abs_sig;     /* crossing number, determinant, |signature| */
} torus_case;

static void check_torus(const torus_case *tc, double hand, int n, gsl_rng *rng, int nrot)
{
  char what[200];
  double *xyz = malloc(3 * (size_t)n * sizeof *xyz);
  long poly[CABLE_KNOT_TYPE_MAX_DEGREE + 1];
  int deg = knot_type_torus_alexander(tc->p, tc->q, poly, CABLE_KNOT_TYPE_MAX_DEGREE);
  for (int rot = 0; rot <= nrot; rot++) {
    torus_curve(tc->p, tc->q, hand, n, xyz);
    if (rot > 0) random_rotate(rng, n, xyz);
    cable_knot_type_result r;
    int rc = knot_type_identify(xyz, n, &r);
    const char *hs = hand > 0 ? "right" : "left";
    snprintf(what, sizeof what, "T(%d,%d) %s, rotation %d: identified as %s (got %s, %d crossings, %d projections agree)",
             tc->p, tc->q, hs, rot, tc->name, rc == 0 ? r.name : "error", r.ncross, r.nagree);
    test_true(what, rc == 0 && strcmp(r.name, tc->name) == 0);
    if (rc != 0) continue;
    snprintf(what, sizeof what, "T(%d,%d) %s, rotation %d: handedness", tc->p, tc->q, hs, rot);
    test_int(what, r.handedness, hand > 0 ? 1 : -1);
    snprintf(what, sizeof what, "T(%d,%d) %s, rotation %d: signature", tc->p, tc->q, hs, rot);
    test_int(what, r.signature, hand > 0 ? -tc->abs_sig : tc->abs_sig);
    if (rot == 0) {
      snprintf(what, sizeof what, "T(%d,%d): Alexander polynomial is the torus-knot polynomial", tc->p, tc->q);
      test_true(what, poly_is(&r, poly, deg));
      snprintf(what, sizeof what, "T(%d,%d): determinant", tc->p, tc->q);
      test_int(what, r.determinant, tc->det);
      snprintf(what, sizeof what, "T(%d,%d): crossing number", tc->p, tc->q);
      test_int(what, r.crossing_number, tc->crossings);
      snprintf(what, sizeof what, "T(%d,%d): projection has at least the crossing number", tc->p, tc->q);
      test_true(what, r.ncross >= tc->crossings);
    }
  }
  free(xyz);
}

static void check_polynomials(void)
{
  long c[CABLE_KNOT_TYPE_MAX_DEGREE + 1];
  /* expanded by hand / sympy: (t^pq - 1)(t - 1)/((t^p - 1)(t^q - 1)) */
  static const long t32[] = {1, -1, 1}, t52[] = {1, -1, 1, -1, 1}, t43[] = {1, -1, 0, 1, 0, -1, 1};
  static const long t54[] = {1, -1, 0, 0, 1, 0, -1, 0, 1, 0, 0, -1, 1};
  static const long t53[] = {1, -1, 0, 1, -1, 1, 0, -1, 1};
  struct { int p, q; const long *c; int deg; } tab[] = {
    {3, 2, t32, 2}, {2, 3, t32, 2}, {5, 2, t52, 4}, {4, 3, t43, 6}, {5, 4, t54, 12}, {5, 3, t53, 8}};
  for (size_t i = 0; i < sizeof tab / sizeof tab[0]; i++) {
    int d = knot_type_torus_alexander(tab[i].p, tab[i].q, c, CABLE_KNOT_TYPE_MAX_DEGREE);
    int ok = d == tab[i].deg;
    for (int k = 0; ok && k <= d; k++) ok = c[k] == tab[i].c[k];
    char what[80];
    snprintf(what, sizeof what, "torus polynomial T(%d,%d)", tab[i].p, tab[i].q);
    test_true(what, ok);
  }
  test_int("torus polynomial: p, q not coprime", knot_type_torus_alexander(4, 2, c, 10), -1);
  test_int("torus polynomial: degree above maxdeg", knot_type_torus_alexander(5, 4, c, 11), -1);
  test_int("crossing number T(5,4)", knot_type_torus_crossings(5, 4), 15);
  test_int("crossing number T(4,5)", knot_type_torus_crossings(4, 5), 15);
}

static void check_figure_eight(gsl_rng *rng)
{
  int n = 800;
  double *xyz = malloc(3 * (size_t)n * sizeof *xyz);
  static const long f8[] = {-1, 3, -1};
  for (int rot = 0; rot <= 3; rot++) {
    figure_eight(n, xyz);
    if (rot > 0) random_rotate(rng, n, xyz);
    cable_knot_type_result r;
    int rc = knot_type_identify(xyz, n, &r);
    char what[160];
    snprintf(what, sizeof what, "figure-eight, rotation %d: identified (got %s, %d crossings)", rot,
             rc == 0 ? r.name : "error", r.ncross);
    test_true(what, rc == 0 && strcmp(r.name, "figure-eight") == 0);
    if (rc) continue;
    test_true("figure-eight: Alexander polynomial -1 + 3t - t^2", poly_is(&r, f8, 2));
    test_int("figure-eight: signature 0", r.signature, 0);
    test_int("figure-eight: amphichiral (handedness 0)", r.handedness, 0);
    test_int("figure-eight: determinant 5", r.determinant, 5);
    test_int("figure-eight: crossing number 4", r.crossing_number, 4);
  }
  free(xyz);
}

static void check_unknots(void)
{
  int n = 1000;
  double *xyz = malloc(3 * (size_t)n * sizeof *xyz);
  static const long one[] = {1};
  cable_knot_type_result r;
  char what[160];
  /* side views of the wobbly circle */
  wobbly_circle(n, xyz);
  const double dirs[3][3] = {{1, 0.013, 0.021}, {0.017, 1, 0.029}, {0.7, 0.7, 0.05}};
  for (int k = 0; k < 3; k++) {
    int rc = knot_type_identify_dir(xyz, n, dirs[k], &r);
    snprintf(what, sizeof what, "wobbly circle, side view %d: unknot from %d crossings", k, rc == 0 ? r.ncross : -1);
    test_true(what, rc == 0 && strcmp(r.name, "unknot") == 0 && poly_is(&r, one, 0));
    snprintf(what, sizeof what, "wobbly circle, side view %d: many crossings (>= 10)", k);
    test_true(what, rc == 0 && r.ncross >= 10);
    test_int("wobbly circle: signature 0", r.signature, 0);
  }
  test_int("wobbly circle: automatic projection", knot_type_identify(xyz, n, &r), 0);
  test_true("wobbly circle: unknot", strcmp(r.name, "unknot") == 0 && r.crossing_number == 0);
  /* T(7,1) and T(1,6) are unknots whose projections along and across z cross */
  torus_curve(7, 1, 1.0, n, xyz);
  const double dz[3] = {0.011, 0.007, 1.0}, dx[3] = {1.0, 0.013, 0.009};
  int rc = knot_type_identify_dir(xyz, n, dz, &r);
  snprintf(what, sizeof what, "T(7,1) seen from above: unknot with %d crossings", rc == 0 ? r.ncross : -1);
  test_true(what, rc == 0 && strcmp(r.name, "unknot") == 0 && r.ncross >= 6);
  torus_curve(1, 6, 1.0, n, xyz);
  rc = knot_type_identify_dir(xyz, n, dx, &r);
  snprintf(what, sizeof what, "T(1,6) seen from the side: unknot with %d crossings", rc == 0 ? r.ncross : -1);
  test_true(what, rc == 0 && strcmp(r.name, "unknot") == 0 && r.ncross >= 5);
  free(xyz);
}

static void check_errors(void)
{
  double tri[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  cable_knot_type_result r;
  test_int("n < 3", knot_type_identify(tri, 2, &r), CABLE_ERR_INPUT);
  test_int("NULL coordinates", knot_type_identify(NULL, 3, &r), CABLE_ERR_INPUT);
  test_int("NULL result", knot_type_identify(tri, 3, NULL), CABLE_ERR_INPUT);
  test_int("triangle: unknot", knot_type_identify(tri, 3, &r), 0);
  test_true("triangle: name unknot, no crossing", strcmp(r.name, "unknot") == 0 && r.ncross == 0);
  tri[4] = NAN;
  test_int("NaN coordinate", knot_type_identify(tri, 3, &r), CABLE_ERR_NONFINITE);
  tri[4] = 0;
  const double zero[3] = {0, 0, 0}, inplane[3] = {1, 0, 0};
  test_int("zero projection direction", knot_type_identify_dir(tri, 3, zero, &r), CABLE_ERR_INPUT);
  test_int("projection along the plane of a triangle is degenerate",
           knot_type_identify_dir(tri, 3, inplane, &r), CABLE_ERR_INPUT);
  double sq[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  const double diag[3] = {1, 1, 0};
  test_int("projection along the plane of a square (sides overlap) is degenerate",
           knot_type_identify_dir(sq, 4, diag, &r), CABLE_ERR_INPUT);
  /* a planar lemniscate crosses itself: no projection separates the strands */
  int n = 400;
  double *xyz = malloc(3 * (size_t)12000 * sizeof *xyz);
  for (int i = 0; i < n; i++) {
    double u = 2 * M_PI * i / n + 0.001;
    xyz[3 * i] = sin(u);
    xyz[3 * i + 1] = sin(u) * cos(u);
    xyz[3 * i + 2] = 0.0;
  }
  test_int("self-intersecting curve refused", knot_type_identify(xyz, n, &r), CABLE_ERR_INPUT);
  /* T(41,5) has crossing number 164 > KNOT_TYPE_MAX_CROSSINGS in every projection */
  torus_curve(41, 5, 1.0, 12000, xyz);
  test_int("too many crossings refused", knot_type_identify(xyz, 12000, &r), CABLE_ERR_UNSUPPORTED);
  free(xyz);
}

int main(void)
{
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, 20240607);
  check_polynomials();
  const torus_case cases[] = {
    {3, 2, "trefoil", 3, 3, 2}, {2, 3, "trefoil", 3, 3, 2}, {5, 2, "torus(5,2)", 5, 5, 4},
    {4, 3, "torus(4,3)", 8, 3, 6}, {3, 4, "torus(4,3)", 8, 3, 6}, {5, 4, "torus(5,4)", 15, 5, 8},
    {7, 2, "torus(7,2)", 7, 7, 6}, {5, 3, "torus(5,3)", 10, 1, 8}};
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
    check_torus(&cases[i], 1.0, 1200, rng, 2);
    check_torus(&cases[i], -1.0, 1200, rng, 2);
  }
  check_figure_eight(rng);
  check_unknots();
  check_errors();
  gsl_rng_free(rng);
  return test_summary();
}
