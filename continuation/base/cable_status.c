/* SPDX-License-Identifier: GPL-3.0-or-later */
#include "cable/cable_status.h"

typedef struct {
  int code;
  const char *name;
  const char *message;
} status_entry;

static const status_entry status_table[] = {
#define CABLE_STATUS_ROW(name, value, msg) {value, #name, msg},
  CABLE_STATUS_TABLE(CABLE_STATUS_ROW)
#undef CABLE_STATUS_ROW
};

static const status_entry *status_find(int status)
{
  for (unsigned i = 0; i < sizeof status_table / sizeof status_table[0]; i++)
    if (status_table[i].code == status) return &status_table[i];
  return 0;
}

const char *cable_status_message(int status)
{
  const status_entry *e = status_find(status);
  return e ? e->message : "unknown status";
}

const char *cable_status_name(int status)
{
  const status_entry *e = status_find(status);
  return e ? e->name : "CABLE_STATUS_UNKNOWN";
}
