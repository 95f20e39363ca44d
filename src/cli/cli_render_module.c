/* The one table of the render module bgdraw_render.so (cli_render.h). It is
 * the module's only object file: linking it pulls in exactly the renderers
 * it names. */
#include "cli/cli_render.h"

#include "scene/style.h"
#include "scene/surface.h"

const bg_render_api bg_render_module = {
    BG_RENDER_API_VERSION, bg_diagram_build,   bg_diagram_free, bg_diagram_write,
    bg_diagram_render,     bg_show_parse,      bg_highlight_parse, bg_plot_write,
    bg_plot_linear_write,  bg_report_write,    bg_style_path,   bg_render_versions,
    bg_fonts_own,
};
