/* SPDX-License-Identifier: GPL-3.0-or-later */
#include "cable/cable_names.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>

#include "cable/cable_output.h"

void cable_names_init(cable_names *n)
{
  if (n) memset(n, 0, sizeof *n);
}

int cable_names_par_index(const cable_names *n, const char *name,
                          const char *const *parnames, int npar)
{
  if (!name || !name[0]) return -1;
  if (n)
    for (int k = 0; k < CABLE_NAMES_MAX; k++)
      if (n->par[k][0] && strcmp(n->par[k], name) == 0) return k;
  if (parnames)
    for (int k = 0; k < npar; k++)
      if (parnames[k] && strcmp(parnames[k], name) == 0) return k;
  return -1;
}

int cable_names_u_index(const cable_names *n, const char *name)
{
  if (!n || !name || !name[0]) return -1;
  for (int i = 0; i < CABLE_NAMES_MAX; i++)
    if (n->u[i][0] && strcmp(n->u[i], name) == 0) return i;
  return -1;
}

static int names_used(char tab[][CABLE_NAME_LEN], const char *name)
{
  for (int k = 0; k < CABLE_NAMES_MAX; k++)
    if (tab[k][0] && strcmp(tab[k], name) == 0) return 1;
  return 0;
}

static void names_fill_one(char tab[][CABLE_NAME_LEN], const char *const *src, int count)
{
  if (!src) return;
  if (count > CABLE_NAMES_MAX) count = CABLE_NAMES_MAX;
  for (int k = 0; k < count; k++) {
    const char *s = src[k];
    if (!s || !s[0] || tab[k][0] || strlen(s) >= CABLE_NAME_LEN || names_used(tab, s)) continue;
    strcpy(tab[k], s);
  }
}

void cable_names_fill(cable_names *n, const char *const *parnames, int npar,
                      const char *const *unames, int ndim)
{
  if (!n) return;
  names_fill_one(n->par, parnames, npar);
  names_fill_one(n->u, unames, ndim);
}

typedef struct {
  int code;
  const char *name;
} type_entry;

/* The point types an IPS=4 run produces (AUTO's LBTYPE for BVPs). */
static const type_entry type_table[] = {
  {CABLE_TY_BP, "BP"}, {CABLE_TY_LP, "LP"}, {CABLE_TY_UZ, "UZ"},
  {CABLE_TY_EP, "EP"}, {CABLE_TY_MX, "MX"}, {CABLE_TY_RG, "RG"},
};
#define TYPE_TABLE_N ((int)(sizeof type_table / sizeof type_table[0]))

int cable_type_base(int itp)
{
  return itp % 10;   /* C's remainder keeps the sign: -14 -> -4 (no overflow at INT_MIN) */
}

const char *cable_type_name(int itp)
{
  int base = cable_type_base(itp);
  for (int i = 0; i < TYPE_TABLE_N; i++)
    if (type_table[i].code == base) return type_table[i].name;
  return "";
}

int cable_type_code(const char *name)
{
  if (!name) return 0;
  for (int i = 0; i < TYPE_TABLE_N; i++)
    if (strcmp(type_table[i].name, name) == 0) return type_table[i].code;
  return 0;
}

int cable_label_spec_parse(const char *spec, int *type, int *nth)
{
  if (!spec || strlen(spec) < 3) return -1;
  char tname[3] = {spec[0], spec[1], '\0'};
  int code = cable_type_code(tname);
  if (code == 0) return -1;
  const char *p = spec + 2;
  for (const char *q = p; *q; q++)
    if (!isdigit((unsigned char)*q)) return -1;
  long v = strtol(p, NULL, 10);
  if (v < 1 || v > 1000000) return -1;
  if (type) *type = code;
  if (nth) *nth = (int)v;
  return 0;
}
