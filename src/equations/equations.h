/* SPDX-License-Identifier: BSD-3-Clause */
/* The equations stage's front door (docs/equations.md): the equation system
 * (eqsys.h) and its layout for the exporters (eqtape.h), its printers
 * (eqprint.h), its symbols and reduced form (eqsym.h), the numeric index
 * (index.h) and index reduction (indexred.h). Other stages include this
 * header only; eqsys_int.h and indexred_int.h are internal to the stage. */
#ifndef BG_EQUATIONS_H
#define BG_EQUATIONS_H
#include "equations/eqprint.h"
#include "equations/eqsym.h"
#include "equations/eqsys.h"
#include "equations/eqtape.h"
#include "equations/index.h"
#include "equations/indexred.h"
#endif
