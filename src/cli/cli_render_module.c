/* SPDX-License-Identifier: BSD-3-Clause */
/* The one table of the render module bgdraw_render.so (cli_render.h). It is
 * the module's only object file: linking it pulls in exactly the renderers
 * it names. */
#include "cli/cli_render.h"

#include "scene/style.h"
#include "scene/surface.h"

#define ENTRY_R(ret, name, params, args) .name = bg_##name,
#define ENTRY_V(name, params, args) .name = bg_##name,
const bg_render_api bg_render_module = {
    .version = BG_RENDER_API_VERSION,
    BG_RENDER_CALLS(ENTRY_R, ENTRY_V)
};
