/* libFuzzer target: the constants-file parser (auto_iface/files/constants_parse.c).
 * The input is the text of a c. file; the first half of it is also tried as a
 * KEY=VALUE override on the parsed constants, the path `cable run KEY=VALUE`
 * and script keywords take.  Built by scripts/fuzz.sh. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "cable/cable_constants.h"

/* The braid problems' own parameter names, so that names in PAR={...},
 * ICP=[...] and UZR={...} resolve and the code behind resolution runs. */
static const char *const fuzz_parnames[] = {"T", "L", "L2", "eps21", "F", "Delta", "Ltot"};

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  char *text = malloc(size + 1);
  if (!text) return 0;
  memcpy(text, data, size);
  text[size] = '\0';
  cable_constants c;
  cable_names names;
  cable_error err;
  cable_constants_init(&c);
  cable_names_init(&names);
  int npar = (int)(sizeof fuzz_parnames / sizeof fuzz_parnames[0]);
  if (cable_constants_parse_string("fuzz", text, &c, &names, fuzz_parnames, npar, &err) == 0) {
    text[size / 2] = '\0';
    (void)cable_constants_parse_override(text, &c, &names, fuzz_parnames, npar, &err);
  }
  free(text);
  return 0;
}
