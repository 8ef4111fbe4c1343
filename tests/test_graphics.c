/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Pictures and exports: nice ticks, rotation-minimising frames and tube
 * meshes against closed forms, bifurcation diagrams (PNG header, SVG
 * well-formedness), rendered torus-knot tubes (pixel statistics against the
 * geometry, depth order at a crossing), VTK and PLY counts, error paths. */
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include <cairo/cairo.h>

#include "cable/cable_status.h"
#include "export.h"
#include "graphics_file.h"
#include "graphics_text.h"
#include "harness.h"
#include "plot.h"
#include "plot_ticks.h"
#include "render.h"
#include "render_raster.h"
#include "tube_mesh.h"

#define PI 3.14159265358979323846
#define OUTDIR "tests/tmp/graphics"
#define SIZE 200 /* test pictures are SIZE x SIZE: fast, still hundreds of tube pixels */

/* ------------------------------------------------------------------ files */

static char *slurp(const char *path, long *len)
{
  FILE *f = fopen(path, "rb");
  if (f == NULL) return NULL;
  fseek(f, 0, SEEK_END);
  long n = ftell(f);
  fseek(f, 0, SEEK_SET);
  char *buf = malloc((size_t)n + 1);
  if (buf && fread(buf, 1, (size_t)n, f) != (size_t)n) {
    free(buf);
    buf = NULL;
  }
  fclose(f);
  if (buf) buf[n] = '\0';
  if (len) *len = n;
  return buf;
}

static int file_exists(const char *path)
{
  struct stat st;
  return stat(path, &st) == 0;
}

/* Temporary files the atomic writers might have left in OUTDIR. */
static int leftover_temporaries(void)
{
  DIR *d = opendir(OUTDIR);
  if (d == NULL) return -1;
  int n = 0;
  struct dirent *e;
  while ((e = readdir(d)) != NULL) n += strstr(e->d_name, ".tmp") != NULL;
  closedir(d);
  return n;
}

static unsigned long be32(const unsigned char *p)
{
  return (unsigned long)p[0] << 24 | (unsigned long)p[1] << 16 | (unsigned long)p[2] << 8 | p[3];
}

/* PNG signature, first chunk IHDR, its width and height. */
static void check_png_header(const char *what, const char *path, long w, long h)
{
  long len = 0;
  unsigned char *b = (unsigned char *)slurp(path, &len);
  static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  char name[160];
  snprintf(name, sizeof name, "%s: PNG signature", what);
  test_true(name, b != NULL && len > 33 && memcmp(b, sig, 8) == 0);
  snprintf(name, sizeof name, "%s: IHDR chunk first, 13 bytes", what);
  test_true(name, b != NULL && len > 33 && be32(b + 8) == 13 && memcmp(b + 12, "IHDR", 4) == 0);
  snprintf(name, sizeof name, "%s: IHDR width", what);
  test_int(name, b && len > 33 ? (long)be32(b + 16) : -1, w);
  snprintf(name, sizeof name, "%s: IHDR height", what);
  test_int(name, b && len > 33 ? (long)be32(b + 20) : -1, h);
  free(b);
}

/* ---------------------------------------------------- XML well-formedness */

#define XML_MAX_NODES 256
#define XML_MAX_DEPTH 64

typedef struct {
  char name[48];
  int parent;
  const char *attr, *attr_end;  /* attribute text */
  const char *text, *text_end;  /* character data directly inside (first run) */
} xml_node;

typedef struct {
  xml_node node[XML_MAX_NODES];
  int n;
  int roots;
  char error[128];
} xml_doc;

static int xml_fail(xml_doc *d, const char *msg, const char *at, const char *base)
{
  snprintf(d->error, sizeof d->error, "%s at offset %ld", msg, (long)(at - base));
  return 0;
}

static int xml_name_char(char c)
{
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '-' || c == ':' || c == '.';
}

/* Entity references must be one of XML's five or a character reference. */
static int xml_text_ok(const char *p, const char *end)
{
  for (; p < end; p++) {
    if (*p == '>') continue;
    if (*p != '&') continue;
    const char *semi = memchr(p, ';', (size_t)(end - p));
    if (semi == NULL) return 0;
    size_t n = (size_t)(semi - p - 1);
    const char *e = p + 1;
    if (!((n == 3 && !strncmp(e, "amp", 3)) || (n == 2 && !strncmp(e, "lt", 2)) ||
          (n == 2 && !strncmp(e, "gt", 2)) || (n == 4 && !strncmp(e, "quot", 4)) ||
          (n == 4 && !strncmp(e, "apos", 4)) || (n >= 2 && e[0] == '#')))
      return 0;
    p = semi;
  }
  return 1;
}

/* Balanced, properly nested tags with quoted attributes, exactly one root
 * element and nothing but white space outside it. */
static int xml_parse(const char *s, xml_doc *d)
{
  const char *p = s;
  int stack[XML_MAX_DEPTH], depth = 0;
  d->n = 0, d->roots = 0, d->error[0] = '\0';
  while (*p) {
    if (*p != '<') {
      const char *q = strchr(p, '<');
      const char *end = q ? q : p + strlen(p);
      if (!xml_text_ok(p, end)) return xml_fail(d, "bad entity", p, s);
      if (depth == 0) {
        for (const char *c = p; c < end; c++)
          if (*c != ' ' && *c != '\n' && *c != '\r' && *c != '\t') return xml_fail(d, "text outside root", c, s);
      } else {
        xml_node *top = d->node + stack[depth - 1];
        if (top->text == NULL) top->text = p, top->text_end = end;
      }
      p = end;
      continue;
    }
    if (!strncmp(p, "<?", 2)) {
      const char *q = strstr(p, "?>");
      if (q == NULL) return xml_fail(d, "unterminated <?", p, s);
      p = q + 2;
    } else if (!strncmp(p, "<!--", 4)) {
      const char *q = strstr(p + 4, "-->");
      if (q == NULL) return xml_fail(d, "unterminated comment", p, s);
      p = q + 3;
    } else if (!strncmp(p, "<![CDATA[", 9)) {
      const char *q = strstr(p, "]]>");
      if (q == NULL || depth == 0) return xml_fail(d, "bad CDATA", p, s);
      p = q + 3;
    } else if (!strncmp(p, "<!", 2)) {
      const char *q = strchr(p, '>');
      if (q == NULL) return xml_fail(d, "unterminated <!", p, s);
      p = q + 1;
    } else if (p[1] == '/') {
      const char *q = p + 2;
      while (xml_name_char(*q)) q++;
      size_t n = (size_t)(q - p - 2);
      while (*q == ' ' || *q == '\n' || *q == '\t' || *q == '\r') q++;
      if (*q != '>') return xml_fail(d, "bad end tag", p, s);
      if (depth == 0) return xml_fail(d, "end tag without start", p, s);
      const char *open = d->node[stack[depth - 1]].name;
      if (strlen(open) != n || strncmp(open, p + 2, n) != 0) return xml_fail(d, "mismatched end tag", p, s);
      depth--;
      p = q + 1;
    } else {
      const char *q = p + 1;
      while (xml_name_char(*q)) q++;
      size_t n = (size_t)(q - p - 1);
      if (n == 0 || n >= sizeof d->node[0].name) return xml_fail(d, "bad tag name", p, s);
      if (depth == 0 && ++d->roots > 1) return xml_fail(d, "second root element", p, s);
      if (d->n >= XML_MAX_NODES || depth >= XML_MAX_DEPTH) return xml_fail(d, "too many nodes", p, s);
      xml_node *node = d->node + d->n;
      memcpy(node->name, p + 1, n);
      node->name[n] = '\0';
      node->parent = depth ? stack[depth - 1] : -1;
      node->attr = q;
      node->text = node->text_end = NULL;
      /* attributes: name="value" or name='value', no '<' inside values */
      for (;;) {
        while (*q == ' ' || *q == '\n' || *q == '\t' || *q == '\r') q++;
        if (*q == '>' || (q[0] == '/' && q[1] == '>')) break;
        const char *a = q;
        while (xml_name_char(*q)) q++;
        if (q == a || *q != '=') return xml_fail(d, "bad attribute", q, s);
        char quote = *++q;
        if (quote != '"' && quote != '\'') return xml_fail(d, "unquoted attribute", q, s);
        const char *v = ++q;
        while (*q && *q != quote && *q != '<') q++;
        if (*q != quote || !xml_text_ok(v, q)) return xml_fail(d, "bad attribute value", v, s);
        q++;
      }
      node->attr_end = q;
      int empty = *q == '/';
      p = q + (empty ? 2 : 1);
      if (!empty) stack[depth++] = d->n;
      d->n++;
    }
  }
  if (depth != 0) return xml_fail(d, "unclosed element", p, s);
  if (d->roots != 1) return xml_fail(d, "no root element", p, s);
  return 1;
}

/* Value of attribute `name` of a node ("" when absent). */
static void xml_attr(const xml_node *nd, const char *name, char *out, size_t len)
{
  out[0] = '\0';
  size_t n = strlen(name);
  for (const char *p = nd->attr; p + n + 2 < nd->attr_end; p++) {
    if ((p == nd->attr || p[-1] == ' ' || p[-1] == '\n') && !strncmp(p, name, n) && p[n] == '=') {
      const char *v = p + n + 2, *e = memchr(v, p[n + 1], (size_t)(nd->attr_end - v));
      if (e == NULL) return;
      size_t m = (size_t)(e - v) < len - 1 ? (size_t)(e - v) : len - 1;
      memcpy(out, v, m);
      out[m] = '\0';
      return;
    }
  }
}

static long xml_attr_long(const xml_node *nd, const char *name)
{
  char buf[64];
  xml_attr(nd, name, buf, sizeof buf);
  return buf[0] ? strtol(buf, NULL, 10) : -1;
}

/* Whitespace-separated numbers in a node's text; the largest and the last
 * one are returned too (for connectivity and offsets). */
static long xml_count_numbers(const xml_node *nd, double *max, double *last)
{
  long n = 0;
  *max = -INFINITY, *last = NAN;
  if (nd->text == NULL) return 0;
  const char *p = nd->text;
  while (p < nd->text_end) {
    char *end;
    double v = strtod(p, &end);
    if (end == p) {
      p++;
      continue;
    }
    n++;
    *max = fmax(*max, v);
    *last = v;
    p = end;
  }
  return n;
}

/* ------------------------------------------------------------- curves */

/* The (7, 2) torus knot as a pair of strands twisting about a circle of
 * radius R at distance a from it (contact-distance Delta = 2a): strand k
 * (k = 0, 1) at angle phi in [0, 2 pi] is C(phi) + a (cos th N + sin th B),
 * th = 3.5 phi + k pi, N radial, B = z.  The end of strand 0 is the start of
 * strand 1, so together they are one closed curve. */
static void torus72_strand(int k, int n, double R, double a, double *xyz)
{
  for (int i = 0; i < n; i++) {
    double phi = 2 * PI * i / (n - 1), th = 3.5 * phi + k * PI;
    xyz[3 * i] = (R + a * cos(th)) * cos(phi);
    xyz[3 * i + 1] = (R + a * cos(th)) * sin(phi);
    xyz[3 * i + 2] = a * sin(th);
  }
}

/* ------------------------------------------------------------- ticks */

static void test_ticks(void)
{
  plot_ticks t;
  test_int("ticks [0,1]: status", plot_ticks_nice(0, 1, 5, &t), CABLE_SUCCESS);
  test_abs("ticks [0,1]: step 0.2", t.step, 0.2, 1e-15);
  test_int("ticks [0,1]: 6 ticks", t.n, 6);
  test_abs("ticks [0,1]: last tick 1", plot_ticks_value(&t, t.n - 1), 1.0, 1e-15);
  /* Fig. 12.2's torque range (captions of Figs. 12.3-12.6) */
  plot_ticks_nice(-15.51471, -2.10752, 5, &t);
  test_abs("ticks T in [-15.5,-2.1]: step 2 (raw 13.4/5 = 2.68 rounds to 2)", t.step, 2.0, 0);
  test_true("ticks T: limits enclose the data", t.lo <= -15.51471 && t.hi >= -2.10752);
  test_abs("ticks T: lo = -16", t.lo, -16.0, 0);
  test_abs("ticks T: hi = -2", t.hi, -2.0, 0);
  plot_ticks_nice(171.50131, 942.989, 5, &t);
  test_abs("ticks F in [171.5,943]: step 200 (raw 154 -> 2e2)", t.step, 200.0, 0);
  test_abs("ticks F: lo 0", t.lo, 0.0, 0);
  test_abs("ticks F: hi 1000", t.hi, 1000.0, 0);
  test_int("ticks F: 6 ticks", t.n, 6);
  /* every step is 1, 2 or 5 x 10^k and the ticks enclose the data */
  int ok = 1;
  for (int e = -7; e <= 7; e++)
    for (int j = 1; j < 20; j++) {
      double lo = -0.37 * j * pow(10.0, e), hi = 1.13 * j * j * pow(10.0, e);
      if (plot_ticks_nice(lo, hi, 6, &t) != CABLE_SUCCESS) ok = 0;
      double m = t.step / pow(10.0, floor(log10(t.step) + 1e-12));
      if (fabs(m - 1) > 1e-9 && fabs(m - 2) > 1e-9 && fabs(m - 5) > 1e-9) ok = 0;
      if (t.lo > lo || t.hi < hi || t.n < 3 || t.n > 16) ok = 0;
    }
  test_true("ticks: 1-2-5 steps enclosing the data over 15 decades", ok);
  char buf[64];
  plot_ticks_nice(0, 1, 5, &t);
  plot_ticks_format(&t, plot_ticks_value(&t, 2), buf, sizeof buf);
  test_true("ticks: label 0.4", strcmp(buf, "0.4") == 0);
  plot_ticks_nice(-1, 1, 4, &t);
  plot_ticks_format(&t, 1e-17, buf, sizeof buf);
  test_true("ticks: round-off zero prints as 0.0", strcmp(buf, "0.0") == 0);
  plot_ticks_nice(1e7, 5e7, 4, &t);
  plot_ticks_format(&t, 2e7, buf, sizeof buf);
  test_true("ticks: large values in exponent form (2e+07)", strcmp(buf, "2e+07") == 0);
  plot_ticks_nice(3, 3, 5, &t);
  test_true("ticks: a single value gets a range around it", t.lo < 3 && t.hi > 3 && t.n >= 3);
  test_int("ticks: NaN limit rejected", plot_ticks_nice(NAN, 1, 5, &t), CABLE_ERR_INPUT);
  test_int("ticks: target 0 rejected", plot_ticks_nice(0, 1, 0, &t), CABLE_ERR_INPUT);
}

/* ------------------------------------------------------------- frames */

/* Angle of normal r in the exact Frenet (N, B) plane of the helix
 * (cos u, sin u, c u). */
static double helix_angle(double c, double u, const double r[3])
{
  double s = sqrt(1 + c * c);
  double T[3] = {-sin(u) / s, cos(u) / s, c / s}, N[3] = {-cos(u), -sin(u), 0}, B[3];
  B[0] = T[1] * N[2] - T[2] * N[1];
  B[1] = T[2] * N[0] - T[0] * N[2];
  B[2] = T[0] * N[1] - T[1] * N[0];
  return atan2(r[0] * B[0] + r[1] * B[1] + r[2] * B[2], r[0] * N[0] + r[1] * N[1] + r[2] * N[2]);
}

/* Largest error of the discrete rotation-minimising frame's twist against
 * the exact one, theta(s) - theta(s_m) = -tau (s - s_m), over the middle
 * half of an open helix of n points (the ends use one-sided tangents). */
static double helix_twist_error(int n)
{
  const double c = 0.5, umax = 4 * PI, tau = c / (1 + c * c), speed = sqrt(1 + c * c);
  double *xyz = malloc(sizeof(double) * 3 * (size_t)n), *t = malloc(sizeof(double) * 3 * (size_t)n);
  double *r = malloc(sizeof(double) * 3 * (size_t)n);
  for (int i = 0; i < n; i++) {
    double u = umax * i / (n - 1);
    xyz[3 * i] = cos(u), xyz[3 * i + 1] = sin(u), xyz[3 * i + 2] = c * u;
  }
  double err = INFINITY;
  if (tube_frames_compute(n, xyz, 0, t, r, NULL) == CABLE_SUCCESS) {
    err = 0;
    int m = n / 2;
    double um = umax * m / (n - 1), am = helix_angle(c, um, r + 3 * m);
    for (int i = n / 4; i <= 3 * n / 4; i++) {
      double u = umax * i / (n - 1);
      double d = helix_angle(c, u, r + 3 * i) - am + tau * speed * (u - um);
      d = remainder(d, 2 * PI);
      err = fmax(err, fabs(d));
    }
  }
  free(xyz), free(t), free(r);
  return err;
}

static void test_frames(void)
{
  enum { NC = 64 };
  double xyz[3 * NC], t[3 * NC], r[3 * NC], phi = 1;
  for (int i = 0; i < NC; i++) {
    double u = 2 * PI * i / NC;
    xyz[3 * i] = 0.3 * cos(u), xyz[3 * i + 1] = 0.3 * sin(u), xyz[3 * i + 2] = 0.1;
  }
  test_int("frames: circle", tube_frames_compute(NC, xyz, 1, t, r, &phi), CABLE_SUCCESS);
  /* a plane curve's frame with the binormal (or principal normal) is
   * rotation-minimising: transport round the loop closes exactly, up to
   * round-off accumulated over NC reflections */
  test_le("frames: circle closes without correction |phi|", fabs(phi), 1e-12);
  double worst = 0;
  for (int i = 0; i < NC; i++) {
    const double *ti = t + 3 * i, *ri = r + 3 * i;
    worst = fmax(worst, fabs(ti[0] * ri[0] + ti[1] * ri[1] + ti[2] * ri[2]));
    worst = fmax(worst, fabs(sqrt(ri[0] * ri[0] + ri[1] * ri[1] + ri[2] * ri[2]) - 1));
  }
  test_le("frames: orthonormal to round-off", worst, 1e-14);

  /* Wang et al. (2008) show the double-reflection frame is a fourth-order
   * approximation of the rotation-minimising frame given exact tangents.
   * Ours are bisectors of unit chords, tilted by O(h^2) towards the helix
   * axis by the same amount at every point; the tilt changes both
   * reflections alike and the twist stays fourth order (an independent
   * NumPy transcription gives orders 4.0000 with exact tangents and 4.0005
   * with bisector tangents between n = 201 and 401). */
  double e1 = helix_twist_error(201), e2 = helix_twist_error(401);
  double order = log(e1 / e2) / log(400.0 / 200.0);
  printf("     helix twist error n=201: %.3e, n=401: %.3e, observed order %.3f\n", e1, e2, order);
  test_abs("frames: helix twist converges at order 4", order, 4.0, 0.3);
  /* 24 points per turn and a second order leading term would give ~1e-3 */
  test_le("frames: helix twist error at n=401", e2, 1e-7);

  /* closed (7,2) knot: transport misses by phi, spread over the loop, so the
   * seam turns no more than its neighbours */
  enum { NK = 400 };
  double *k = malloc(sizeof(double) * 3 * (2 * NK + 1)), *tk = malloc(sizeof(double) * 3 * 2 * NK);
  double *rk = malloc(sizeof(double) * 3 * 2 * NK);
  torus72_strand(0, NK + 1, 0.15, 0.0025, k);           /* last point = first of strand 1 */
  torus72_strand(1, NK + 1, 0.15, 0.0025, k + 3 * NK);  /* last point = first of strand 0 */
  int nk = tube_points_count(2 * NK + 1, k, 1);
  test_int("frames: repeated end point of a closed curve dropped", nk, 2 * NK);
  tube_frames_compute(nk, k, 1, tk, rk, &phi);
  printf("     knot closure angle before correction: %.6f rad\n", phi);
  double seam = 0, inner = 0;
  for (int i = 0; i < nk; i++) {
    int j = (i + 1) % nk;
    double d = rk[3 * i] * rk[3 * j] + rk[3 * i + 1] * rk[3 * j + 1] + rk[3 * i + 2] * rk[3 * j + 2];
    double ang = acos(fmin(1.0, d));
    if (j == 0) seam = ang;
    else inner = fmax(inner, ang);
  }
  test_true("frames: knot transport does not close by itself (|phi| > 1e-3)", fabs(phi) > 1e-3);
  /* without the correction the seam would turn |phi| more than elsewhere */
  test_le("frames: knot seam turn <= largest turn elsewhere + |phi|/10", seam, inner + fabs(phi) / 10);
  free(k), free(tk), free(rk);

  double bad[6] = {1, 2, 3, 1, 2, 3};
  test_int("frames: coincident points rejected", tube_frames_compute(2, bad, 0, t, r, NULL), CABLE_ERR_INPUT);
  bad[4] = NAN;
  test_int("frames: NaN rejected", tube_frames_compute(2, bad, 0, t, r, NULL), CABLE_ERR_INPUT);
  test_int("frames: n < 2 rejected", tube_frames_compute(1, xyz, 0, t, r, NULL), CABLE_ERR_INPUT);
}

static int cmp_long(const void *a, const void *b)
{
  long x = *(const long *)a, y = *(const long *)b;
  return (x > y) - (x < y);
}

static void test_mesh(void)
{
  enum { N = 50, S = 12 };
  double xyz[3 * N], sc[N], radius = 0.05;
  for (int i = 0; i < N; i++) {
    double u = 3.0 * i / (N - 1);
    xyz[3 * i] = cos(u), xyz[3 * i + 1] = sin(u), xyz[3 * i + 2] = 0.4 * u;
    sc[i] = i;
  }
  int nv, ntri;
  tube_mesh_counts(N, S, 0, &nv, &ntri);
  test_int("mesh: open vertices N S + 2 (S + 1)", nv, N * S + 2 * (S + 1));
  test_int("mesh: open triangles 2 (N - 1) S + 2 S", ntri, 2 * (N - 1) * S + 2 * S);
  tube_mesh *m = tube_mesh_alloc(N, S, 0);
  test_int("mesh: build", m ? tube_mesh_build(m, xyz, sc, radius) : -99, CABLE_SUCCESS);
  if (m == NULL) return;
  double derr = 0, perp = 0;
  for (int i = 0; i < N; i++)
    for (int j = 0; j < S; j++) {
      const double *v = m->xyz + 3 * (i * S + j), *c = xyz + 3 * i, *t = m->t + 3 * i;
      double d[3] = {v[0] - c[0], v[1] - c[1], v[2] - c[2]};
      derr = fmax(derr, fabs(sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - radius) / radius);
      perp = fmax(perp, fabs(d[0] * t[0] + d[1] * t[1] + d[2] * t[2]) / radius);
    }
  test_le("mesh: ring vertices at the radius (rel.)", derr, 1e-14);
  test_le("mesh: rings perpendicular to the tangent", perp, 1e-14);
  /* every triangle faces outwards: its geometric normal agrees with its
   * vertices' normals */
  int inward = 0;
  for (int k = 0; k < m->ntri; k++) {
    const int *tr = m->tri + 3 * k;
    const double *a = m->xyz + 3 * tr[0], *b = m->xyz + 3 * tr[1], *c = m->xyz + 3 * tr[2];
    double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    double g[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    double dot = 0;
    for (int q = 0; q < 3; q++)
      for (int a3 = 0; a3 < 3; a3++) dot += g[a3] * m->normal[3 * tr[q] + a3];
    inward += dot <= 0;
  }
  test_int("mesh: triangles oriented outwards (count inward)", inward, 0);
  test_abs("mesh: end cap carries the end scalar", m->scalar[m->nv - 1], N - 1, 0);
  tube_mesh_free(m);

  /* a closed tube is a closed, consistently oriented surface: every directed
   * edge occurs once and its reverse occurs once */
  enum { NK = 120 };
  double k[3 * NK];
  for (int i = 0; i < NK; i++) {
    double u = 2 * PI * i / NK;
    k[3 * i] = 0.1 * cos(u), k[3 * i + 1] = 0.1 * sin(u), k[3 * i + 2] = 0.02 * sin(3 * u);
  }
  m = tube_mesh_alloc(NK, S, 1);
  tube_mesh_build(m, k, NULL, 0.001);
  long ne = 3L * m->ntri, *edge = malloc(sizeof *edge * (size_t)ne);
  for (long e = 0; e < ne; e++) {
    long t = e / 3, a = m->tri[3 * t + e % 3], b = m->tri[3 * t + (e + 1) % 3];
    edge[e] = a * m->nv + b;
  }
  qsort(edge, (size_t)ne, sizeof *edge, cmp_long);
  long bad = 0;
  for (long e = 0; e < ne; e++) {
    long a = edge[e] / m->nv, b = edge[e] % m->nv, rev = b * m->nv + a;
    bad += (e > 0 && edge[e] == edge[e - 1]) ||
           bsearch(&rev, edge, (size_t)ne, sizeof *edge, cmp_long) == NULL;
  }
  test_int("mesh: closed tube is a closed oriented surface (bad edges)", bad, 0);
  free(edge);
  tube_mesh_free(m);
  tube_mesh_free(NULL);
  test_true("mesh: alloc rejects 2 sides", tube_mesh_alloc(N, 2, 0) == NULL);
  test_true("mesh: alloc rejects 1 point", tube_mesh_alloc(1, S, 0) == NULL);
}

/* ------------------------------------------------------------- plots */

static int rgb_at(cairo_surface_t *s, int x, int y, int c[3]);

/* Pixels that are colour rgb blended over white with weight >= 1/2 (the
 * middle of an anti-aliased line), to within tol in 0-255 units. */
static long count_blend(cairo_surface_t *s, const double rgb[3], int tol)
{
  int w = cairo_image_surface_get_width(s), h = cairo_image_surface_get_height(s);
  long n = 0;
  int k = 0; /* the channel that separates the colour from white best */
  for (int a = 1; a < 3; a++)
    if (rgb[a] < rgb[k]) k = a;
  for (int y = 0; y < h; y++)
    for (int x = 0; x < w; x++) {
      int c[3];
      rgb_at(s, x, y, c);
      double wt = (255.0 - c[k]) / (255.0 * (1.0 - rgb[k]));
      if (wt < 0.5 || wt > 1.0 + tol / 255.0) continue;
      int ok = 1;
      for (int a = 0; a < 3; a++) ok &= fabs(c[a] - 255.0 * (1.0 - wt * (1.0 - rgb[a]))) <= tol;
      n += ok;
    }
  return n;
}

/* Pixels darker than half grey in every channel. */
static long count_dark(cairo_surface_t *s)
{
  int w = cairo_image_surface_get_width(s), h = cairo_image_surface_get_height(s);
  long n = 0;
  for (int y = 0; y < h; y++)
    for (int x = 0; x < w; x++) {
      int c[3];
      rgb_at(s, x, y, c);
      n += c[0] < 128 && c[1] < 128 && c[2] < 128;
    }
  return n;
}

/* Pixels within tol (0-255 units, each channel) of colour rgb. */
static long count_color(cairo_surface_t *s, const double rgb[3], int tol, int x0, int x1)
{
  int w = cairo_image_surface_get_width(s), h = cairo_image_surface_get_height(s);
  int stride = cairo_image_surface_get_stride(s);
  const unsigned char *d = cairo_image_surface_get_data(s);
  long n = 0;
  if (x1 > w) x1 = w;
  for (int y = 0; y < h; y++)
    for (int x = x0; x < x1; x++) {
      unsigned px;
      memcpy(&px, d + (size_t)y * (size_t)stride + 4 * (size_t)x, sizeof px);
      int c[3] = {(int)(px >> 16 & 255), (int)(px >> 8 & 255), (int)(px & 255)};
      int ok = 1;
      for (int a = 0; a < 3; a++) ok &= abs(c[a] - (int)lround(255 * rgb[a])) <= tol;
      n += ok;
    }
  return n;
}

static void plot_data(double *x0, double *y0, int *ty0, double *x1, double *y1, int *ty1, int *lab1)
{
  /* a v-shaped trivial branch with branch points and one bifurcating branch */
  for (int i = 0; i < 41; i++) {
    x0[i] = -20 + i;
    y0[i] = 100 + 40 * fabs(x0[i] + 1);
    ty0[i] = (i == 10 || i == 15 || i == 30) ? 6 : 0;
  }
  for (int i = 0; i < 30; i++) {
    x1[i] = -10 - 0.2 * i;
    y1[i] = 460 + 12 * i + 0.3 * i * i;
    ty1[i] = i == 0 ? 6 : i == 29 ? 9 : 0;
    lab1[i] = i == 20 ? 7 : i == 29 ? 8 : 0;
  }
  y0[5] = NAN;  /* a gap in the polyline */
}

static void test_plot(void)
{
  double x0[41], y0[41], x1[30], y1[30];
  int ty0[41], ty1[30], lab1[30];
  plot_data(x0, y0, ty0, x1, y1, ty1, lab1);
  plot_branch b[2] = {{"trivial", 41, x0, y0, ty0, NULL, NULL}, {"mode 1", 30, x1, y1, ty1, lab1, NULL}};
  plot_options o = {"T", "F", "(7,2) torus knot", 400, 300, PLOT_FORMAT_PNG};
  const char *png = OUTDIR "/bif.png", *svg = OUTDIR "/bif.svg";
  test_int("plot: PNG written", plot_bifurcation(b, 2, &o, png), CABLE_SUCCESS);
  check_png_header("plot", png, 400, 300);
  cairo_surface_t *s = cairo_image_surface_create_from_png(png);
  test_true("plot: PNG decodes", cairo_surface_status(s) == CAIRO_STATUS_SUCCESS);
  double c0[3], c1[3];
  plot_branch_color(0, c0);
  plot_branch_color(1, c1);
  /* tol 12: the blend weight is estimated from one 8-bit channel */
  long n0 = count_blend(s, c0, 12), n1 = count_blend(s, c1, 12), ndark = count_dark(s);
  printf("     pixels: branch 0 colour %ld, branch 1 colour %ld, dark %ld\n", n0, n1, ndark);
  /* each branch spans a good part of the 400 px plot width */
  test_true("plot: branch 0 drawn in its colour (>= 100 px)", n0 >= 100);
  test_true("plot: branch 1 drawn in its colour (>= 100 px)", n1 >= 100);
  cairo_surface_destroy(s);
  /* the same without types: the four filled branch-point circles go away;
   * each covers at least pi (2.5 px)^2 = 20 px (radius 0.32 x the smallest
   * font size, 8 px) */
  plot_branch bn[2] = {{"trivial", 41, x0, y0, NULL, NULL, NULL}, {"mode 1", 30, x1, y1, NULL, lab1, NULL}};
  const char *png2 = OUTDIR "/bif_notype.png";
  plot_bifurcation(bn, 2, &o, png2);
  s = cairo_image_surface_create_from_png(png2);
  long ndark2 = count_dark(s);
  cairo_surface_destroy(s);
  printf("     dark pixels with branch points %ld, without %ld\n", ndark, ndark2);
  test_true("plot: filled branch-point circles add >= 4 x 20 dark px", ndark - ndark2 >= 80);

  o.format = PLOT_FORMAT_SVG;
  cable_plot_annotation an[2] = {{-2.10752, 171.5, "(a)", 0}, {-9.89105, 368.075, "(b)", 0}};
  test_int("plot: SVG written", plot_bifurcation_annotated(b, 2, an, 2, &o, svg), CABLE_SUCCESS);
  char *text = slurp(svg, NULL);
  xml_doc *d = calloc(1, sizeof *d);
  int ok = text && xml_parse(text, d);
  if (!ok) printf("     SVG: %s\n", d->error);
  test_true("plot: SVG well-formed", ok);
  test_true("plot: SVG root is <svg>", ok && strcmp(d->node[0].name, "svg") == 0);
  char wbuf[32] = "", hbuf[32] = "";
  if (ok) xml_attr(d->node, "width", wbuf, sizeof wbuf), xml_attr(d->node, "height", hbuf, sizeof hbuf);
  test_int("plot: SVG width", strtol(wbuf, NULL, 10), 400);
  test_int("plot: SVG height", strtol(hbuf, NULL, 10), 300);
  /* the checker itself rejects broken documents */
  test_true("xml checker: rejects crossed tags", !xml_parse("<svg><g></svg></g>", d));
  test_true("xml checker: rejects two roots", !xml_parse("<svg/><svg/>", d));
  test_true("xml checker: rejects unquoted attribute", !xml_parse("<svg a=1/>", d));
  test_true("xml checker: rejects unclosed root", !xml_parse("<svg><g/>", d));
  test_true("xml checker: rejects bad entity", !xml_parse("<svg>a & b</svg>", d));
  test_true("xml checker: accepts a minimal document", xml_parse("<?xml version=\"1.0\"?>\n<svg a='1'><g/></svg>\n", d));
  free(d);
  free(text);

  /* errors: nothing written, an existing file untouched */
  FILE *f = fopen(OUTDIR "/keep.png", "w");
  fputs("old", f);
  fclose(f);
  o.format = PLOT_FORMAT_PNG;
  double nan2[2] = {NAN, NAN};
  plot_branch allnan = {"nan", 2, nan2, nan2, NULL, NULL, NULL};
  test_int("plot error: no finite point", plot_bifurcation(&allnan, 1, &o, OUTDIR "/keep.png"), CABLE_ERR_INPUT);
  char *kept = slurp(OUTDIR "/keep.png", NULL);
  test_true("plot error: existing file untouched", kept && strcmp(kept, "old") == 0);
  free(kept);
  test_int("plot error: NULL branches", plot_bifurcation(NULL, 1, &o, png), CABLE_ERR_INPUT);
  test_int("plot error: no branch", plot_bifurcation(b, 0, &o, png), CABLE_ERR_INPUT);
  plot_branch empty = {"e", 0, x0, y0, NULL, NULL, NULL}, nox = {"x", 3, NULL, y0, NULL, NULL, NULL};
  test_int("plot error: n < 1", plot_bifurcation(&empty, 1, &o, png), CABLE_ERR_INPUT);
  test_int("plot error: NULL x", plot_bifurcation(&nox, 1, &o, png), CABLE_ERR_INPUT);
  test_int("plot error: NULL options", plot_bifurcation(b, 2, NULL, png), CABLE_ERR_INPUT);
  o.format = 7;
  test_int("plot error: unknown format", plot_bifurcation(b, 2, &o, png), CABLE_ERR_INPUT);
  o.format = PLOT_FORMAT_PNG;
  o.width = 20, o.height = 20;
  test_int("plot error: too small for a plot area", plot_bifurcation(b, 2, &o, png), CABLE_ERR_INPUT);
  o.width = 400, o.height = 300;
  test_int("plot error: unwritable path (PNG)", plot_bifurcation(b, 2, &o, OUTDIR "/no/such/dir/a.png"), CABLE_ERR_IO);
  o.format = PLOT_FORMAT_SVG;
  test_int("plot error: unwritable path (SVG)", plot_bifurcation(b, 2, &o, OUTDIR "/no/such/dir/a.svg"), CABLE_ERR_IO);
  test_true("plot error: nothing created", !file_exists(OUTDIR "/no"));
}

/* Bounding box [x0, x1] x [y0, y1] of the pixels that differ between two
 * images of equal size; returns their number. */
static long diff_bbox(cairo_surface_t *a, cairo_surface_t *b, int box[4])
{
  int w = cairo_image_surface_get_width(a), h = cairo_image_surface_get_height(a);
  long n = 0;
  box[0] = w, box[1] = h, box[2] = -1, box[3] = -1;
  for (int y = 0; y < h; y++)
    for (int x = 0; x < w; x++) {
      int ca[3], cb[3];
      rgb_at(a, x, y, ca);
      rgb_at(b, x, y, cb);
      if (ca[0] == cb[0] && ca[1] == cb[1] && ca[2] == cb[2]) continue;
      n++;
      if (x < box[0]) box[0] = x;
      if (y < box[1]) box[1] = y;
      if (x > box[2]) box[2] = x;
      if (y > box[3]) box[3] = y;
    }
  return n;
}

static cairo_surface_t *plot_to_surface(const plot_branch *b, int nb, const cable_plot_annotation *an, int na,
                                        const char *path)
{
  plot_options o = {"T", "F", NULL, 400, 300, PLOT_FORMAT_PNG};
  if (plot_bifurcation_annotated(b, nb, an, na, &o, path) != CABLE_SUCCESS) return NULL;
  return cairo_image_surface_create_from_png(path);
}

/* STAB=1 diagrams (doc/stability.md S6): a stretch between two unstable
 * points is dashed, the rest solid.  Dashing the right half of a line changes
 * pixels only right of those that dashing its left half changes (but for the
 * point where both switch). */
static void test_plot_dashed(void)
{
  double x[11], y[11];
  int right[11], left[11];
  for (int i = 0; i < 11; i++) x[i] = i, y[i] = 100 + 10 * i, right[i] = i >= 5, left[i] = i <= 5;
  plot_branch solid = {"line", 11, x, y, NULL, NULL, NULL};
  plot_branch dr = {"line", 11, x, y, NULL, NULL, right}, dl = {"line", 11, x, y, NULL, NULL, left};
  cairo_surface_t *s0 = plot_to_surface(&solid, 1, NULL, 0, OUTDIR "/dash0.png");
  cairo_surface_t *s1 = plot_to_surface(&dr, 1, NULL, 0, OUTDIR "/dash1.png");
  cairo_surface_t *s2 = plot_to_surface(&dl, 1, NULL, 0, OUTDIR "/dash2.png");
  int br[4] = {0}, bl[4] = {0};
  long nr = s0 && s1 ? diff_bbox(s0, s1, br) : 0, nl = s0 && s2 ? diff_bbox(s0, s2, bl) : 0;
  char buf[200];
  snprintf(buf, sizeof buf, "plot: unstable stretches are dashed (%ld and %ld pixels change; right half x %d..%d, "
           "left half x %d..%d)", nr, nl, br[0], br[2], bl[0], bl[2]);
  /* the two meet at point 5, where each restarts its stroke with round caps: they may
     share a few pixels there (8: about the line width and its antialiasing) */
  test_true(buf, nr > 0 && nl > 0 && br[0] >= bl[2] - 8 && br[2] > bl[2] + 100 && bl[0] < br[0] - 100);
  if (s0) cairo_surface_destroy(s0);
  if (s1) cairo_surface_destroy(s1);
  if (s2) cairo_surface_destroy(s2);
}

/* Mark labels stay inside the plot area: a mark in the top right corner of
 * the data (knot72_mirror.png's "(a) mirrored" was cut at the right edge) has
 * its text to the left of and below the marker.  Two branches labelled at one
 * point get one joined label ("1, 7": knot72.png's two flat arms at T = 0), not
 * two labels drawn over each other. */
static void test_plot_labels(void)
{
  double x[11], y[11];
  for (int i = 0; i < 11; i++) x[i] = i, y[i] = 100 + 10 * i;
  plot_branch b = {"line", 11, x, y, NULL, NULL, NULL};
  cable_plot_annotation bare = {10, 200, NULL, 0}, text = {10, 200, "(a) mirrored", 0};
  cairo_surface_t *s0 = plot_to_surface(&b, 1, NULL, 0, OUTDIR "/lab0.png");
  cairo_surface_t *s1 = plot_to_surface(&b, 1, &bare, 1, OUTDIR "/lab1.png");
  cairo_surface_t *s2 = plot_to_surface(&b, 1, &text, 1, OUTDIR "/lab2.png");
  int mk[4], tx[4];
  long nm = s0 && s1 && s2 ? diff_bbox(s0, s1, mk) : 0, nt = nm ? diff_bbox(s1, s2, tx) : 0;
  test_true("plot labels: the marker and its text are drawn", nm > 0 && nt > 0);
  double cx = 0.5 * (mk[0] + mk[2]), cy = 0.5 * (mk[1] + mk[3]);
  char buf[200];
  /* the difference may include the legend, which moves away from the label */
  snprintf(buf, sizeof buf, "plot labels: a top-right mark's text (and all else it changes) lies left of and below"
           " it (changes x %d..%d y %d..%d, marker at %.0f, %.0f)", tx[0], tx[2], tx[1], tx[3], cx, cy);
  test_true(buf, nt > 0 && tx[2] < cx && tx[1] > cy);
  if (s0) cairo_surface_destroy(s0);
  if (s1) cairo_surface_destroy(s1);
  if (s2) cairo_surface_destroy(s2);

  /* two branches starting at (0, 100), labelled 1 and 7 there */
  int lab1[11] = {1}, lab7[11] = {7}, lab0[11] = {0};
  plot_branch two[2] = {{"a", 11, x, y, NULL, lab1, NULL}, {"b", 11, x, y, NULL, lab7, NULL}};
  plot_branch one[2] = {{"a", 11, x, y, NULL, lab1, NULL}, {"b", 11, x, y, NULL, lab0, NULL}};
  plot_branch none[2] = {{"a", 11, x, y, NULL, lab0, NULL}, {"b", 11, x, y, NULL, lab0, NULL}};
  cairo_surface_t *n0 = plot_to_surface(none, 2, NULL, 0, OUTDIR "/lab3.png");
  cairo_surface_t *n1 = plot_to_surface(one, 2, NULL, 0, OUTDIR "/lab4.png");
  cairo_surface_t *n2 = plot_to_surface(two, 2, NULL, 0, OUTDIR "/lab5.png");
  int b1[4], b2[4];
  long d1 = n0 && n1 && n2 ? diff_bbox(n0, n1, b1) : 0, d2 = d1 ? diff_bbox(n0, n2, b2) : 0;
  /* ", 7" adds at least two character widths: at the smallest font (8 px)
   * more than 6 px; labels drawn over each other add none */
  snprintf(buf, sizeof buf, "plot labels: labels 1 and 7 at one point are joined (widths %d and %d px)",
           d1 ? b1[2] - b1[0] + 1 : 0, d2 ? b2[2] - b2[0] + 1 : 0);
  test_true(buf, d1 > 0 && d2 > 0 && (b2[2] - b2[0]) - (b1[2] - b1[0]) > 6);
  if (n0) cairo_surface_destroy(n0);
  if (n1) cairo_surface_destroy(n1);
  if (n2) cairo_surface_destroy(n2);
}

/* ------------------------------------------------------------- render */

typedef struct {
  long covered;     /* pixels that are not background */
  long distinct;    /* distinct colours */
  long red, blue;   /* pixels of the two strands' hues */
} pixel_stats;

/* A pixel is covered when some channel is below 160: more than a third of
 * its area belongs to a tube (background is white, tubes are saturated). */
#define COVER_LEVEL 160

static int rgb_at(cairo_surface_t *s, int x, int y, int c[3])
{
  int stride = cairo_image_surface_get_stride(s);
  unsigned px;
  memcpy(&px, cairo_image_surface_get_data(s) + (size_t)y * (size_t)stride + 4 * (size_t)x, sizeof px);
  c[0] = (int)(px >> 16 & 255), c[1] = (int)(px >> 8 & 255), c[2] = (int)(px & 255);
  return c[0] < COVER_LEVEL || c[1] < COVER_LEVEL || c[2] < COVER_LEVEL;
}

static int is_red(const int c[3])
{
  return c[0] > 2 * c[1] + 10 && c[0] > 2 * c[2] + 10;
}

static int is_blue(const int c[3])
{
  return c[2] > 2 * c[0] + 10 && c[2] > c[1] + 10;
}

static pixel_stats image_stats(const char *path)
{
  pixel_stats st = {0, 0, 0, 0};
  cairo_surface_t *s = cairo_image_surface_create_from_png(path);
  if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(s);
    return st;
  }
  int w = cairo_image_surface_get_width(s), h = cairo_image_surface_get_height(s);
  unsigned char *seen = calloc(1u << 21, 1); /* one bit per 24-bit colour */
  for (int y = 0; y < h; y++)
    for (int x = 0; x < w; x++) {
      int c[3];
      st.covered += rgb_at(s, x, y, c);
      st.red += is_red(c), st.blue += is_blue(c);
      unsigned key = (unsigned)(c[0] << 16 | c[1] << 8 | c[2]);
      if (!(seen[key >> 3] & (1u << (key & 7)))) seen[key >> 3] |= (unsigned char)(1u << (key & 7)), st.distinct++;
    }
  free(seen);
  cairo_surface_destroy(s);
  return st;
}

/* Expected covered fraction of the knot picture: a band along the core
 * circle (length 2 pi R) whose width is that of two discs of drawn radius r
 * whose centres are +-a cos(th) apart across the band, i.e. 2 r + 2 a |cos th|,
 * 2 r + (4/pi) a on average over th. */
static double knot_coverage(const render_camera *cam, double R, double a, double r)
{
  double width = 2 * r + 4 / PI * a;
  return 2 * PI * R * width * cam->scale * cam->scale / ((double)cam->width * cam->height);
}

/* The pixel statistics a rendered (7,2) knot must show, each a yes/no:
 * coverage within 15 % of the tube geometry's (boundary pixels count when a
 * third covered, +-0.5 px on a band about 8 px wide, 6 %; ring facets,
 * cos(pi/13) = 0.97, 3 %; the band's width varying along the knot), shading
 * (>= 50 distinct colours), and each strand's colour on >= 25 % of the
 * covered pixels (by symmetry each strand is in front half the time), with
 * something covered at all. */
#define KNOT_COVER_TOL 0.15
#define KNOT_MIN_COLOURS 50

typedef struct {
  int coverage, shading, red, blue;
} knot_verdict;

static knot_verdict knot_pixel_checks(const pixel_stats *st, long npix, double want)
{
  double cover = (double)st->covered / (double)npix;
  knot_verdict v;
  v.coverage = isfinite(cover) && want > 0 && fabs(cover - want) <= KNOT_COVER_TOL * want;
  v.shading = st->distinct >= KNOT_MIN_COLOURS;
  v.red = st->covered > 0 && st->red >= st->covered / 4;
  v.blue = st->covered > 0 && st->blue >= st->covered / 4;
  return v;
}

/* The checks reject what is not a rendered knot: a blank image, an image of
 * one colour, and a band of one flat colour covering exactly the knot's
 * expected area (so only the shading and strand checks can catch it). */
static void test_knot_checks_negative(double want)
{
  const char *path[3] = {OUTDIR "/blank.png", OUTDIR "/grey.png", OUTDIR "/flatband.png"};
  for (int k = 0; k < 3; k++) {
    cairo_surface_t *s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, SIZE, SIZE);
    cairo_t *cr = cairo_create(s);
    cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
    cairo_set_source_rgb(cr, k == 1 ? 0.5 : 1.0, k == 1 ? 0.5 : 1.0, k == 1 ? 0.5 : 1.0);
    cairo_paint(cr);
    if (k == 2) {
      /* an annulus about the centre of area want x SIZE^2 and width 8 px */
      double w = 8, rmid = want * SIZE * SIZE / (2 * PI * w);
      cairo_set_source_rgb(cr, 0.85, 0.12, 0.10);
      cairo_arc(cr, SIZE / 2.0, SIZE / 2.0, rmid + w / 2, 0, 2 * PI);
      cairo_arc_negative(cr, SIZE / 2.0, SIZE / 2.0, rmid - w / 2, 2 * PI, 0);
      cairo_fill(cr);
    }
    cairo_destroy(cr);
    cairo_surface_write_to_png(s, path[k]);
    cairo_surface_destroy(s);
    pixel_stats st = image_stats(path[k]);
    knot_verdict v = knot_pixel_checks(&st, (long)SIZE * SIZE, want);
    char buf[200];
    static const char *const what[3] = {"a blank image", "a single-colour image", "a flat one-colour band of the knot's area"};
    snprintf(buf, sizeof buf, "render checks reject %s (covered %ld, %ld colours, red %ld, blue %ld: coverage %s,"
             " shading %s, strands %s)", what[k], st.covered, st.distinct, st.red, st.blue, v.coverage ? "ok" : "fails",
             v.shading ? "ok" : "fails", v.red && v.blue ? "ok" : "fail");
    test_true(buf, !(v.coverage && v.shading && v.red && v.blue));
    if (k == 2) test_true("  the band has the knot's coverage: only shading and strand colours reject it", v.coverage);
  }
}

static void test_render_knot(void)
{
  enum { N = 400 };
  const double R = 0.15, delta = 0.0051364907419, a = delta / 2;
  double *s0 = malloc(sizeof(double) * 3 * N), *s1 = malloc(sizeof(double) * 3 * N);
  torus72_strand(0, N, R, a, s0);
  torus72_strand(1, N, R, a, s1);
  render_tube tubes[2] = {{N, s0, NULL, a, {0.85, 0.12, 0.10}, 0}, {N, s1, NULL, a, {0.10, 0.25, 0.85}, 0}};
  cable_render_options o = {SIZE, SIZE, {0, 0, 0}, {0, 0, 0}, CABLE_RENDER_COLORMAP_NONE, 2.0};
  const char *png = OUTDIR "/knot72.png";
  test_int("render: (7,2) knot", render_tubes_png(tubes, 2, NULL, 0, &o, png), CABLE_SUCCESS);
  check_png_header("render", png, SIZE, SIZE);
  render_camera cam;
  render_camera_fit(tubes, 2, &o, &cam);
  test_abs("render: default view along least extent (-z)", cam.view[2], -1.0, 1e-12);
  pixel_stats st = image_stats(png);
  double cover = (double)st.covered / (SIZE * SIZE), want = knot_coverage(&cam, R, a, a * cam.thicken);
  printf("     knot: covered %.4f (geometry %.4f), %ld colours, red %ld, blue %ld, thicken %g\n", cover,
         want, st.distinct, st.red, st.blue, cam.thicken);
  knot_verdict v = knot_pixel_checks(&st, (long)SIZE * SIZE, want);
  test_true("render: coverage matches the tube geometry (within 15 %)", v.coverage);
  test_true("render: shading gives >= 50 distinct colours", v.shading);
  test_true("render: strand 1 colour on >= 25 % of covered pixels", v.red);
  test_true("render: strand 2 colour on >= 25 % of covered pixels", v.blue);
  test_knot_checks_negative(want);

  /* the paper's thin strands, automatic thickening: the drawn radius is
   * RENDER_MIN_RADIUS_PX, and the band is as wide as that predicts */
  double thin = 0.0008;
  torus72_strand(0, N, R, thin / 2, s0);
  torus72_strand(1, N, R, thin / 2, s1);
  tubes[0].radius = tubes[1].radius = thin / 2;
  o.thicken = 0;
  test_int("render: thin knot, automatic thickening", render_tubes_png(tubes, 2, NULL, 0, &o, OUTDIR "/knot_thin.png"), CABLE_SUCCESS);
  render_camera_fit(tubes, 2, &o, &cam);
  test_rel("render: automatic drawn radius = RENDER_MIN_RADIUS_PX", thin / 2 * cam.thicken * cam.scale,
           RENDER_MIN_RADIUS_PX, 1e-12);
  st = image_stats(OUTDIR "/knot_thin.png");
  cover = (double)st.covered / (SIZE * SIZE);
  want = knot_coverage(&cam, R, thin / 2, thin / 2 * cam.thicken);
  printf("     thin knot: covered %.4f (geometry %.4f), thicken %.3f\n", cover, want, cam.thicken);
  /* a 3 px band: the pixel-threshold error is +-1/3 of its width */
  test_rel("render: thin strands visible as a band of the expected width", cover, want, 0.35);

  /* colour map on both strands' scalar, with a colour bar */
  double *p0 = malloc(sizeof(double) * N), *p1 = malloc(sizeof(double) * N);
  for (int i = 0; i < N; i++) p0[i] = cos(2 * PI * i / (N - 1)), p1[i] = 0.5 * p0[i];
  tubes[0].scalar = p0, tubes[1].scalar = p1;
  o.colormap = CABLE_RENDER_COLORMAP_DIVERGING;
  o.width = 300;
  test_int("render: colour map", render_tubes_png(tubes, 2, NULL, 0, &o, OUTDIR "/knot_cmap.png"), CABLE_SUCCESS);
  render_camera_fit(tubes, 2, &o, &cam);
  cairo_surface_t *s = cairo_image_surface_create_from_png(OUTDIR "/knot_cmap.png");
  const double warm[3] = {0.706, 0.016, 0.150}, cool[3] = {0.230, 0.299, 0.754};
  /* tol 8: the bar's end rows sit half a row (u >= 0.99 for >= 50 rows)
   * inside the map, up to 0.01 x 4 x 0.59 x 255 = 6 units from its ends */
  long nw = count_color(s, warm, 8, cam.plot_width, 300), nc = count_color(s, cool, 8, cam.plot_width, 300);
  long nw_img = count_color(s, warm, 8, 0, cam.plot_width);
  printf("     colour bar: %ld warm-end and %ld cool-end pixels; warm-end pixels left of it %ld\n", nw, nc, nw_img);
  test_true("render: colour bar shows the warm end (one bar row, >= 5 px)", nw >= 5);
  test_true("render: colour bar shows the cool end (one bar row, >= 5 px)", nc >= 5);
  cairo_surface_destroy(s);
  free(p0), free(p1);
  free(s0), free(s1);
}

static void test_render_depth(void)
{
  /* tube A (red) along x at z = +0.2, tube B (blue) along y at z = -0.2 */
  double a[6] = {-1, 0, 0.2, 1, 0, 0.2}, b[6] = {0, -1, -0.2, 0, 1, -0.2};
  render_tube t[2] = {{2, a, NULL, 0.1, {0.9, 0.1, 0.1}, 0}, {2, b, NULL, 0.1, {0.1, 0.2, 0.9}, 0}};
  cable_render_options o = {SIZE, SIZE, {0, 0, -1}, {0, 1, 0}, 0, 1.0};
  const char *png = OUTDIR "/cross.png";
  int cpx[3], apx[3], bpx[3];
  for (int view = 0; view < 2; view++) {
    o.view_dir[2] = view == 0 ? -1 : 1;
    render_tubes_png(t, 2, NULL, 0, &o, png);
    render_camera cam;
    render_camera_fit(t, 2, &o, &cam);
    double x, y, z, xa, ya, xb, yb, cross[3] = {0, 0, 0}, pa[3] = {0.7, 0, 0.2}, pb[3] = {0, 0.7, -0.2};
    render_camera_project(&cam, cross, &x, &y, &z);
    render_camera_project(&cam, pa, &xa, &ya, &z);
    render_camera_project(&cam, pb, &xb, &yb, &z);
    cairo_surface_t *s = cairo_image_surface_create_from_png(png);
    rgb_at(s, (int)x, (int)y, cpx);
    rgb_at(s, (int)xa, (int)ya, apx);
    rgb_at(s, (int)xb, (int)yb, bpx);
    cairo_surface_destroy(s);
    if (view == 0) {
      test_true("render depth: looking down -z, the upper tube (red) is at the crossing", is_red(cpx));
    } else {
      test_true("render depth: looking up +z, the lower tube (blue) is at the crossing", is_blue(cpx));
    }
    test_true("render depth: tube A red away from the crossing", is_red(apx));
    test_true("render depth: tube B blue away from the crossing", is_blue(bpx));
  }

  /* a green profile along the lower tube B: seen over B, hidden where A
   * passes in front */
  enum { NP = 101 };
  double pxyz[3 * NP], pv[NP];
  for (int i = 0; i < NP; i++) {
    pxyz[3 * i] = 0, pxyz[3 * i + 1] = -1 + 2.0 * i / (NP - 1), pxyz[3 * i + 2] = -0.2;
    pv[i] = 0.05;
  }
  render_profile prof = {pxyz, pv, NP, {0, 1, 0}, {0, 1, 0}, 1.0, NULL};
  o.view_dir[2] = -1;
  test_int("render: profile", render_tubes_png(t, 2, &prof, 1, &o, OUTDIR "/cross_profile.png"), CABLE_SUCCESS);
  render_camera cam;
  render_camera_fit(t, 2, &o, &cam);
  cairo_surface_t *s = cairo_image_surface_create_from_png(OUTDIR "/cross_profile.png");
  const double green[3] = {0, 1, 0};
  long ngreen = count_color(s, green, 40, 0, SIZE);
  /* green in the rows of B away from A (11 rows about y = 0.5), none in the
   * rows that A covers (|y| < 0.1 less 2 px for anti-aliased edges) */
  long far = 0, near = 0;
  double x, y, z, q1[3] = {0, 0.5, 0}, q2[3] = {0, 0, 0};
  render_camera_project(&cam, q1, &x, &y, &z);
  int row_far = (int)y;
  render_camera_project(&cam, q2, &x, &y, &z);
  int row_near = (int)y, half = (int)(0.1 * cam.scale) - 2;
  for (int px = 0; px < SIZE; px++) {
    int c[3];
    for (int dy = -5; dy <= 5; dy++) {
      rgb_at(s, px, row_far + dy, c);
      far += c[1] > 200 && c[0] < 60 && c[2] < 60;
    }
    for (int dy = -half; dy <= half; dy++) {
      rgb_at(s, px, row_near + dy, c);
      near += c[1] > 200 && c[0] < 60 && c[2] < 60;
    }
  }
  cairo_surface_destroy(s);
  printf("     profile: %ld green pixels; in 11 rows over B %ld, in the rows where A is in front %ld\n",
         ngreen, far, near);
  /* the line runs the length of B (about 180 px) less the crossing */
  test_true("render: profile drawn (>= 100 green px)", ngreen >= 100);
  test_true("render: profile shows over its own tube (>= 5 px in 11 rows)", far >= 5);
  test_int("render: profile hidden behind the tube in front", near, 0);
}

static void test_render_errors(void)
{
  double a[6] = {-1, 0, 0.2, 1, 0, 0.2};
  render_tube t = {2, a, NULL, 0.1, {0.9, 0.1, 0.1}, 0};
  cable_render_options o = {SIZE, SIZE, {0, 0, 0}, {0, 0, 0}, 0, 1.0};
  const char *png = OUTDIR "/err.png";
  test_int("render error: unwritable path", render_tubes_png(&t, 1, NULL, 0, &o, OUTDIR "/no/such/dir/x.png"), CABLE_ERR_IO);
  test_int("render error: NULL tubes", render_tubes_png(NULL, 1, NULL, 0, &o, png), CABLE_ERR_INPUT);
  test_int("render error: no tube", render_tubes_png(&t, 0, NULL, 0, &o, png), CABLE_ERR_INPUT);
  test_int("render error: NULL path", render_tubes_png(&t, 1, NULL, 0, &o, NULL), CABLE_ERR_INPUT);
  t.n = 1;
  test_int("render error: n < 2", render_tubes_png(&t, 1, NULL, 0, &o, png), CABLE_ERR_INPUT);
  t.n = 2, t.xyz = NULL;
  test_int("render error: NULL xyz", render_tubes_png(&t, 1, NULL, 0, &o, png), CABLE_ERR_INPUT);
  t.xyz = a, t.radius = 0;
  test_int("render error: radius 0", render_tubes_png(&t, 1, NULL, 0, &o, png), CABLE_ERR_INPUT);
  t.radius = 0.1;
  a[4] = NAN;
  test_int("render error: NaN point", render_tubes_png(&t, 1, NULL, 0, &o, png), CABLE_ERR_INPUT);
  a[4] = 0;
  double same[6] = {1, 1, 1, 1, 1, 1};
  t.xyz = same;
  test_int("render error: all points coincide", render_tubes_png(&t, 1, NULL, 0, &o, png), CABLE_ERR_INPUT);
  t.xyz = a;
  render_profile p = {a, NULL, 2, {1, 1, 1}, {0, 0, 0}, 1, NULL};
  test_int("render error: profile without values", render_tubes_png(&t, 1, &p, 1, &o, png), CABLE_ERR_INPUT);
  test_int("render error: NULL profiles with nprof 1", render_tubes_png(&t, 1, NULL, 1, &o, png), CABLE_ERR_INPUT);
  o.colormap = 9;
  test_int("render error: unknown colour map", render_tubes_png(&t, 1, NULL, 0, &o, png), CABLE_ERR_INPUT);
  o.colormap = 0, o.width = RENDER_MAX_SIZE + 1;
  test_int("render error: picture too large", render_tubes_png(&t, 1, NULL, 0, &o, png), CABLE_ERR_INPUT);
  test_true("render error: nothing written", !file_exists(png));
  test_int("render: defaults with opt NULL", render_tubes_png(&t, 1, NULL, 0, NULL, OUTDIR "/defaults.png"), CABLE_SUCCESS);
  check_png_header("render defaults", OUTDIR "/defaults.png", RENDER_DEFAULT_SIZE, RENDER_DEFAULT_SIZE);
  render_zbuf_free(NULL);
  cable_atomic_abort(NULL);
  test_int("atomic file: commit(NULL) is refused", cable_atomic_commit(NULL, NULL), CABLE_ERR_INPUT);
}

/* ------------------------------------------------------------- exports */

static const xml_node *xml_find(const xml_doc *d, const char *name, const char *parent, int nth)
{
  for (int i = 0; i < d->n; i++) {
    const xml_node *nd = d->node + i;
    if (strcmp(nd->name, name) != 0) continue;
    if (parent && (nd->parent < 0 || strcmp(d->node[nd->parent].name, parent) != 0)) continue;
    if (nth-- == 0) return nd;
  }
  return NULL;
}

/* Cells of a <Lines> or <Polys> block: offsets count = cells, connectivity
 * count = last offset, every index < npoints. */
static void check_cells(const xml_doc *d, const char *block, long cells, long npoints, long want_conn)
{
  char what[128];
  const xml_node *conn = NULL, *offs = NULL;
  for (int i = 0; i < d->n; i++) {
    const xml_node *nd = d->node + i;
    if (strcmp(nd->name, "DataArray") || nd->parent < 0 || strcmp(d->node[nd->parent].name, block)) continue;
    char nm[32];
    xml_attr(nd, "Name", nm, sizeof nm);
    if (!strcmp(nm, "connectivity")) conn = nd;
    if (!strcmp(nm, "offsets")) offs = nd;
  }
  double cmax = NAN, clast, omax, olast = NAN;
  long nc = conn ? xml_count_numbers(conn, &cmax, &clast) : -1;
  long no = offs ? xml_count_numbers(offs, &omax, &olast) : -1;
  snprintf(what, sizeof what, "vtp %s: offsets count = declared cells", block);
  test_int(what, no, cells);
  snprintf(what, sizeof what, "vtp %s: connectivity count = last offset", block);
  test_int(what, nc, (long)olast);
  snprintf(what, sizeof what, "vtp %s: connectivity count = expected from the mesh", block);
  test_int(what, nc, want_conn);
  snprintf(what, sizeof what, "vtp %s: indices < NumberOfPoints", block);
  test_true(what, cmax < (double)npoints);
}

static void test_export(void)
{
  enum { N = 60, S = 10 };
  const double R = 0.15, a = 0.01;
  double s0[3 * N], s1[3 * N + 3], sc[N], cxyz[3 * N], cv[N];
  torus72_strand(0, N, R, a, s0);
  /* a closed tube given with its first point repeated: the repeat is dropped */
  for (int i = 0; i <= N; i++) {
    double u = 2 * PI * i / N;
    s1[3 * i] = 0.3 * cos(u), s1[3 * i + 1] = 0.3 * sin(u), s1[3 * i + 2] = 0.05 * sin(3 * u);
  }
  for (int i = 0; i < N; i++) {
    sc[i] = 10.0 + i;
    double phi = 2 * PI * i / (N - 1);
    cxyz[3 * i] = R * cos(phi), cxyz[3 * i + 1] = R * sin(phi), cxyz[3 * i + 2] = 0;
    cv[i] = sin(phi);
  }
  render_tube t[2] = {{N, s0, sc, a, {0.9, 0.1, 0.1}, 0}, {N + 1, s1, NULL, a, {0.1, 0.2, 0.9}, 1}};
  render_profile contact = {cxyz, cv, N, {1, 1, 1}, {1, 1, 1}, 0, NULL};
  export_options eo = {S, "contact_pressure"};
  const char *vtp = OUTDIR "/tubes.vtp", *ply = OUTDIR "/tubes.ply";
  test_int("export: vtp", export_vtp_write(t, 2, &contact, 1, &eo, vtp), CABLE_SUCCESS);
  int nv0, nt0, nv1, nt1;
  tube_mesh_counts(N, S, 0, &nv0, &nt0);
  tube_mesh_counts(N, S, 1, &nv1, &nt1);
  long want_points = nv0 + nv1 + N + N + N;  /* surfaces, two centrelines, contact curve */
  long want_polys = nt0 + nt1;
  char *text = slurp(vtp, NULL);
  xml_doc *d = calloc(1, sizeof *d);
  int ok = text && xml_parse(text, d);
  if (!ok) printf("     vtp: %s\n", d->error);
  test_true("vtp: well-formed XML", ok);
  test_true("vtp: root VTKFile", ok && strcmp(d->node[0].name, "VTKFile") == 0);
  const xml_node *piece = ok ? xml_find(d, "Piece", "PolyData", 0) : NULL;
  test_true("vtp: one Piece", piece != NULL);
  if (ok && piece) {
    long np = xml_attr_long(piece, "NumberOfPoints"), nl = xml_attr_long(piece, "NumberOfLines");
    long npo = xml_attr_long(piece, "NumberOfPolys");
    test_int("vtp: NumberOfPoints = surfaces + centrelines + contact curve", np, want_points);
    test_int("vtp: NumberOfPolys = triangles", npo, want_polys);
    test_int("vtp: NumberOfLines = 2 centrelines + 1 curve", nl, 3);
    double mx, last;
    const xml_node *pts = xml_find(d, "DataArray", "Points", 0);
    test_int("vtp: Points holds 3 NumberOfPoints numbers", pts ? xml_count_numbers(pts, &mx, &last) : -1, 3 * np);
    for (int k = 0; k < 3; k++) {
      const xml_node *arr = xml_find(d, "DataArray", "PointData", k);
      char nm[64], what[200];
      if (arr) xml_attr(arr, "Name", nm, sizeof nm);
      long comps = arr ? xml_attr_long(arr, "NumberOfComponents") : -1;
      if (comps < 0) comps = 1;
      snprintf(what, sizeof what, "vtp: PointData '%s' holds %ld x NumberOfPoints numbers", arr ? nm : "?", comps);
      test_int(what, arr ? xml_count_numbers(arr, &mx, &last) : -1, comps * np);
    }
    const xml_node *sca = xml_find(d, "DataArray", "PointData", 0);
    char nm[64] = "";
    if (sca) xml_attr(sca, "Name", nm, sizeof nm);
    test_true("vtp: scalar named as asked", strcmp(nm, "contact_pressure") == 0);
    /* lines: open centreline N, closed centreline N + 1 (back to its start),
     * contact curve N */
    check_cells(d, "Lines", nl, np, N + (N + 1) + N);
    check_cells(d, "Polys", npo, np, 3 * want_polys);
    /* the contact curve's values are the last N scalars */
    double smax, slast;
    xml_count_numbers(sca, &smax, &slast);
    test_abs("vtp: last scalar is the contact value", slast, cv[N - 1], 1e-15);
    test_abs("vtp: largest scalar is the tube's", smax, sc[N - 1], 0);
  }
  free(d);
  free(text);

  test_int("export: ply", export_ply_write(t, 2, &eo, ply), CABLE_SUCCESS);
  text = slurp(ply, NULL);
  long hv = -1, hf = -1, lines = 0, faces_ok = 1, nprop = 0;
  char *body = text ? strstr(text, "end_header\n") : NULL;
  if (text) {
    char *p = strstr(text, "element vertex ");
    if (p) hv = strtol(p + 15, NULL, 10);
    p = strstr(text, "element face ");
    if (p) hf = strtol(p + 13, NULL, 10);
    for (p = text; body && p < body; p++) nprop += !strncmp(p, "\nproperty ", 10);
  }
  test_true("ply: starts with 'ply' and has end_header", text && !strncmp(text, "ply\nformat ascii 1.0\n", 21) && body);
  test_int("ply: vertex count in header", hv, nv0 + nv1);
  test_int("ply: face count in header", hf, want_polys);
  if (body) {
    body += strlen("end_header\n");
    long vline = 0;
    for (char *p = body; *p;) {
      char *nl = strchr(p, '\n');
      if (nl == NULL) break;
      if (lines >= hv) {
        long k = strtol(p, NULL, 10);
        faces_ok &= k == 3;
      } else {
        /* 10 numbers per vertex: x y z nx ny nz r g b quality */
        int cnt = 0;
        for (char *q = p; q < nl;) {
          char *e;
          strtod(q, &e);
          if (e == q) break;
          cnt++;
          q = e;
        }
        vline += cnt == 10;
      }
      lines++;
      p = nl + 1;
    }
    test_int("ply: lines after header = vertices + faces", lines, hv + hf);
    test_int("ply: every vertex line has the 10 declared properties", vline, hv);
    test_int("ply: 10 vertex properties + 1 face list declared", nprop, 11);
    test_true("ply: every face is a triangle", faces_ok);
  }
  free(text);

  export_options bad = {2, NULL};
  test_int("export error: 2 sides", export_vtp_write(t, 2, NULL, 0, &bad, vtp), CABLE_ERR_INPUT);
  bad.nsides = 0, bad.scalar_name = "a\"b";
  test_int("export error: scalar name with a quote", export_vtp_write(t, 2, NULL, 0, &bad, vtp), CABLE_ERR_INPUT);
  test_int("export error: unwritable vtp", export_vtp_write(t, 2, NULL, 0, NULL, OUTDIR "/no/such/dir/x.vtp"), CABLE_ERR_IO);
  test_int("export error: unwritable ply", export_ply_write(t, 2, NULL, OUTDIR "/no/such/dir/x.ply"), CABLE_ERR_IO);
  t[0].n = 1;
  test_int("export error: n < 2 (vtp)", export_vtp_write(t, 2, NULL, 0, NULL, vtp), CABLE_ERR_INPUT);
  test_int("export error: n < 2 (ply)", export_ply_write(t, 2, NULL, ply), CABLE_ERR_INPUT);
  t[0].n = N, t[0].xyz = NULL;
  test_int("export error: NULL xyz", export_ply_write(t, 2, NULL, ply), CABLE_ERR_INPUT);
  t[0].xyz = s0;
  contact.value = NULL;
  test_int("export error: curve without values", export_vtp_write(t, 2, &contact, 1, NULL, vtp), CABLE_ERR_INPUT);
  sc[3] = NAN;
  test_int("export error: NaN scalar", export_ply_write(t, 2, NULL, ply), CABLE_ERR_INPUT);
  test_int("export error: NULL tubes", export_ply_write(NULL, 1, NULL, ply), CABLE_ERR_INPUT);
}

/* Folds (LP) get an open triangle and a key row in the legend; a PNG's
 * caption is a tEXt chunk right after IHDR with a valid CRC. */
static uint32_t crc_table_value(uint32_t c)
{
  for (int k = 0; k < 8; k++) c = c & 1u ? 0xedb88320u ^ (c >> 1) : c >> 1;
  return c;
}

static void test_plot_folds_caption(void)
{
  double x[11], y[11];
  int ty_none[11] = {0}, ty_fold[11] = {0}, lab5[11] = {0};
  for (int i = 0; i < 11; i++) x[i] = i, y[i] = 100 + 10 * i;
  ty_fold[5] = 5;   /* CABLE_TY_LP */
  lab5[5] = 3;
  plot_branch none = {"line", 11, x, y, ty_none, NULL, NULL}, fold = {"line", 11, x, y, ty_fold, NULL, NULL};
  plot_branch labelled = {"line", 11, x, y, ty_none, lab5, NULL};
  cairo_surface_t *s0 = plot_to_surface(&none, 1, NULL, 0, OUTDIR "/fold0.png");
  cairo_surface_t *s1 = plot_to_surface(&fold, 1, NULL, 0, OUTDIR "/fold1.png");
  cairo_surface_t *s2 = plot_to_surface(&labelled, 1, NULL, 0, OUTDIR "/fold2.png");
  long d0 = s0 ? count_dark(s0) : 0, d1 = s1 ? count_dark(s1) : 0;
  int box[4];
  long dl = s1 && s2 ? diff_bbox(s1, s2, box) : 0;
  printf("     fold: dark pixels without %ld, with a fold %ld; fold against a labelled point: %ld differ\n", d0,
         d1, dl);
  test_true("plot: a fold adds its triangle and the legend's key (more dark pixels)", d1 > d0 + 20);
  test_true("plot: a fold's mark is not a labelled point's circle", dl > 0);
  if (s0) cairo_surface_destroy(s0);
  if (s1) cairo_surface_destroy(s1);
  if (s2) cairo_surface_destroy(s2);

  plot_options o = {"T", "F", NULL, 200, 150, PLOT_FORMAT_PNG};
  const char *cap = "Fig. 1: a line, its fold", *path = OUTDIR "/caption.png";
  test_int("plot caption: written", plot_bifurcation_captioned(&fold, 1, NULL, 0, &o, cap, path), CABLE_SUCCESS);
  unsigned char buf[200] = {0};
  FILE *f = fopen(path, "rb");
  size_t n = f ? fread(buf, 1, sizeof buf, f) : 0;
  if (f) fclose(f);
  size_t len = strlen("Description") + 1 + strlen(cap);
  uint32_t clen = (uint32_t)buf[33] << 24 | (uint32_t)buf[34] << 16 | (uint32_t)buf[35] << 8 | buf[36];
  int ok = n > 33 + 12 + len && memcmp(buf + 12, "IHDR", 4) == 0 && memcmp(buf + 37, "tEXt", 4) == 0 &&
           clen == len && memcmp(buf + 41, "Description", 12) == 0 && memcmp(buf + 53, cap, strlen(cap)) == 0;
  test_true("plot caption: a tEXt chunk \"Description\" after IHDR holds the caption", ok);
  if (ok) {
    uint32_t c = 0xffffffffu;
    for (size_t i = 37; i < 41 + len; i++) c = crc_table_value((c ^ buf[i]) & 0xffu) ^ (c >> 8);
    c ^= 0xffffffffu;
    const unsigned char *q = buf + 41 + len;
    uint32_t stored = (uint32_t)q[0] << 24 | (uint32_t)q[1] << 16 | (uint32_t)q[2] << 8 | q[3];
    test_true("plot caption: the chunk's CRC-32 is right", c == stored);
  }
  cairo_surface_t *back = cairo_image_surface_create_from_png(path);
  test_true("plot caption: the PNG still reads", cairo_surface_status(back) == CAIRO_STATUS_SUCCESS &&
                                                     cairo_image_surface_get_width(back) == 200);
  cairo_surface_destroy(back);
  test_int("plot caption: a newline is refused", plot_bifurcation_captioned(&fold, 1, NULL, 0, &o, "a\nb",
                                                                           OUTDIR "/caption_nl.png"), CABLE_ERR_INPUT);
  test_true("plot caption: nothing written after the refusal", fopen(OUTDIR "/caption_nl.png", "rb") == NULL);
}

/* A profile with `toward` points is drawn towards them in 3-D (above or
 * below a straight tube seen from +z); a colour bar's title goes above the bar. */
static void test_render_toward_title(void)
{
  enum { NT = 41 };
  double a[3 * NT], up[3 * NT], down[3 * NT], v[NT], sc[NT];
  for (int i = 0; i < NT; i++) {
    a[3 * i] = -1 + 2.0 * i / (NT - 1), a[3 * i + 1] = 0, a[3 * i + 2] = 0;
    up[3 * i] = down[3 * i] = a[3 * i], up[3 * i + 1] = 1, down[3 * i + 1] = -1, up[3 * i + 2] = down[3 * i + 2] = 0;
    v[i] = 1, sc[i] = i;
  }
  render_tube t = {NT, a, NULL, 0.05, {0.5, 0.5, 0.5}, 0};
  cable_render_options o = {SIZE, SIZE, {0, 0, -1}, {0, 1, 0}, 0, 1.0};
  double rows[2] = {0, 0};
  for (int k = 0; k < 2; k++) {
    render_profile p = {a, v, NT, {0, 1, 0}, {0, 1, 0}, 0.3, k == 0 ? up : down};
    const char *path = k == 0 ? OUTDIR "/toward_up.png" : OUTDIR "/toward_down.png";
    test_int("render toward: drawn", render_tubes_png(&t, 1, &p, 1, &o, path), CABLE_SUCCESS);
    cairo_surface_t *s = cairo_image_surface_create_from_png(path);
    long n = 0;
    double sum = 0;
    for (int yy = 0; yy < SIZE; yy++)
      for (int xx = 0; xx < SIZE; xx++) {
        int c[3];
        rgb_at(s, xx, yy, c);
        if (c[1] > 200 && c[0] < 60 && c[2] < 60) n++, sum += yy;
      }
    cairo_surface_destroy(s);
    rows[k] = n ? sum / n : -1;
  }
  render_camera cam;
  render_camera_fit(&t, 1, &o, &cam);
  double x, yc, z, q[3] = {0, 0, 0};
  render_camera_project(&cam, q, &x, &yc, &z);
  double off = 0.3 * cam.scale;
  printf("     toward: profile rows %.1f (towards +y) and %.1f (towards -y), tube at %.1f, offset %.1f px\n", rows[0],
         rows[1], yc, off);
  /* the line's centre row within 1.5 px of the curve moved by 0.3 world units */
  test_true("render toward: towards +y the profile is drawn above the tube", fabs(rows[0] - (yc - off)) < 1.5);
  test_true("render toward: towards -y the profile is drawn below the tube", fabs(rows[1] - (yc + off)) < 1.5);

  render_tube ts = {NT, a, sc, 0.05, {0.5, 0.5, 0.5}, 0};
  o.colormap = 1;   /* CABLE_RENDER_COLORMAP_SEQUENTIAL */
  render_text title = {"caption", "contact pressure"};
  test_int("render title: without", render_tubes_png(&ts, 1, NULL, 0, &o, OUTDIR "/bar0.png"), CABLE_SUCCESS);
  test_int("render title: with", render_tubes_png_text(&ts, 1, NULL, 0, &o, &title, OUTDIR "/bar1.png"),
           CABLE_SUCCESS);
  cairo_surface_t *b0 = cairo_image_surface_create_from_png(OUTDIR "/bar0.png");
  cairo_surface_t *b1 = cairo_image_surface_create_from_png(OUTDIR "/bar1.png");
  int box[4];
  long d = diff_bbox(b0, b1, box);
  printf("     colour bar title: %ld pixels differ, rows %d..%d, columns %d..%d\n", d, box[1], box[3], box[0], box[2]);
  /* the bar starts at 12 % of the height (render_colormap.c): the title is above it, in the right strip */
  test_true("render title: drawn above the colour bar", d > 50 && box[3] < 0.12 * SIZE && box[0] > SIZE / 2);
  cairo_surface_destroy(b0);
  cairo_surface_destroy(b1);
}

int main(void)
{
  mkdir("tests/tmp", 0755);
  if (mkdir(OUTDIR, 0755) != 0 && errno != EEXIST) {
    printf("FAIL cannot create %s\n", OUTDIR);
    return 1;
  }
  remove(OUTDIR "/err.png");
  test_ticks();
  test_frames();
  test_mesh();
  test_plot();
  test_plot_labels();
  test_plot_dashed();
  test_plot_folds_caption();
  test_render_knot();
  test_render_depth();
  test_render_errors();
  test_render_toward_title();
  test_export();
  test_int("no temporary files left behind", leftover_temporaries(), 0);
  graphics_text_cleanup();
  return test_summary();
}
