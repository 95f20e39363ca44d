/* SPDX-License-Identifier: BSD-3-Clause */
/* Flattening (language version 2): a model with submodels, `use`d files and
 * instances becomes one flat version 1 AST with qualified names (M1.Ra) and
 * explicit bond numbers, plus the record of where each flat object came from.
 * The model compiler compiles the flat AST as it compiles any version 1 file;
 * a file without components is never flattened. See docs/format.md
 * ("Submodels") for the language and the numbering of flat bonds. */
#ifndef BG_FLATTEN_H
#define BG_FLATTEN_H
#include "base/diag.h"
#include "lang/ast.h"

typedef struct bg_flat_instance {
  const char *name;   /* qualified: "M1", "M1.S" */
  const char *def;    /* the submodel's name */
  int parent;         /* instance index, -1 = the model itself */
  bg_srcloc loc;      /* of the instance's name in its statement */
  int bond_offset;    /* flat bond number = bond_offset + the bond's number in the submodel */
  int bond_span;      /* numbers bond_offset+1 .. bond_offset+bond_span belong to it */
} bg_flat_instance;

/* One bond as written in one scope; a flat bond joins one or more of them
 * through ports. */
typedef struct bg_flat_segment {
  int inst; /* instance index, -1 = the model itself */
  int num;  /* the bond's number in that scope */
} bg_flat_segment;

typedef struct bg_flat {
  bg_ast *ast; /* the flat version 1 AST (owns its strings) */
  bg_flat_instance *inst;
  int ninst;
  int *elem_inst;      /* per ELEMENT statement of ast, in order: instance index or -1 */
  int nelem;
  int *bond_segadr;    /* per BOND statement of ast, in order: first of its segments */
  int *bond_nseg;
  int nbond;
  bg_flat_segment *seg; /* outermost first, then in chain order from tail to head */
  int nseg;
} bg_flat;

/* The largest flat model: statements (elements, junctions, bonds, params,
 * the other statements) after every instance is expanded. The instance
 * whose expansion would cross it is an error (docs/format.md "Submodels"). */
#define BG_FLAT_MAX 1000000L

/* Flattens `ast` (whose file is source ast->file of dg). Used files are read
 * relative to the file that uses them and added to dg's sources. Returns NULL
 * after errors (reported). */
bg_flat *bg_flat_expand(const bg_ast *ast, bg_diags *dg);
void bg_flat_free(bg_flat *f);
#endif
