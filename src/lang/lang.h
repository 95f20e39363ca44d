/* SPDX-License-Identifier: BSD-3-Clause */
/* The lang stage's front door (docs/format.md): the syntax tree (ast.h),
 * the parser (parse.h) and flattening of submodels (flatten.h). Other
 * stages include this header only; the lexer (lex_int.h) and flattening's
 * shared helpers (flatten_int.h) are internal to the stage. */
#ifndef BG_LANG_H
#define BG_LANG_H
#include "lang/ast.h"
#include "lang/flatten.h"
#include "lang/parse.h"
#endif
