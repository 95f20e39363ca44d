/* SPDX-License-Identifier: BSD-3-Clause */
/* Lexer and parser: .bg source text -> bg_ast, with diagnostics. */
#ifndef BG_PARSE_H
#define BG_PARSE_H
#include "lang/ast.h"
#include "base/diag.h"
#include "base/fileio.h" /* bg_read_file, for the parser's callers */

/* Parses src (len bytes; need not be NUL-terminated) of the file `path`.
 * Every syntax error goes to dg (parsing resumes at the next statement), so
 * one run reports them all. Returns the AST (caller frees with
 * bg_ast_free) even when there were errors; NULL only if dg has errors and
 * nothing could be parsed. */
bg_ast *bg_parse_string(const char *path, const char *src, size_t len, bg_diags *dg);
/* The same for source `file` of dg (a used file; 0 is the model file). */
bg_ast *bg_parse_source(const char *path, const char *src, size_t len, int file, bg_diags *dg);
void bg_ast_free(bg_ast *ast);
/* "prefix.name" in arena a (just name when prefix is empty): qualified names. */
const char *bg_ast_join(bg_arena *a, const char *prefix, const char *name);
/* An effort or flow detector (`De v = n`, `Df i = j`): an element statement
 * that declares a name, not an element (docs/format.md, "Detectors"). */
int bg_ast_is_detector(const bg_ast_stmt *s);

#endif
