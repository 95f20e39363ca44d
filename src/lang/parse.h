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
void bg_ast_free(bg_ast *ast);

#endif
