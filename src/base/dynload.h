/* SPDX-License-Identifier: BSD-3-Clause */
/* Libraries opened on first use (base/lapack.h, simulate/simulate_sundials_int.h):
 * open by SONAME or an environment override, look a routine up, and stop the
 * process with status 4 and the loader's reason when either fails, as a
 * missing library at start-up would (the packages depend on them). */
#ifndef BG_BASE_DYNLOAD_H
#define BG_BASE_DYNLOAD_H

/* dlopen(getenv(env) or soname, RTLD_NOW | RTLD_LOCAL); *name gets the file
 * opened (for bg_dynload_sym's message). `what` names the library to the
 * user ("LAPACK", "SUNDIALS"). The handle stays open for the process' life. */
void *bg_dynload_open(const char *what, const char *env, const char *soname, const char **name);
/* The routine `sym` of handle h stored into the function pointer at fn (its
 * size: sizeof(void *)); name as bg_dynload_open gave it. */
void bg_dynload_sym(void *h, const char *what, const char *name, const char *sym, void *fn);
#endif
