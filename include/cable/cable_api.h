/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The export macro of libcable: every function of the public API is declared
 * CABLE_API; the library is compiled with -fvisibility=hidden, so nothing
 * else is visible to programs linked against libcable.so. */
#ifndef CABLE_API_H
#define CABLE_API_H

#if defined(__GNUC__) || defined(__clang__)
#define CABLE_API __attribute__((visibility("default")))
#else
#define CABLE_API
#endif

#endif
