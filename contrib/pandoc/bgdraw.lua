-- SPDX-License-Identifier: BSD-3-Clause
--[[ pandoc Lua filter: ```bgdraw code blocks become bond graph diagrams.

    pandoc doc.md --lua-filter contrib/pandoc/bgdraw.lua -o doc.html

    ```{.bgdraw show=paths highlight=path:1 style=print}
    Se U = 1
    1 j
    R R1 = 2
    bond U -> j
    bond j -> R1
    ```

HTML output gets bgdraw's web SVG inline (searchable text, CSS classes);
other formats get an image: SVG, or PDF for LaTeX/PDF output, kept in pandoc's
media bag (use --extract-media=DIR when writing .tex). Attributes: show,
highlight, style, layout, causality, caption. A model with errors stops the
conversion with bgdraw's diagnostics. BGDRAW in the environment names the
program (default bgdraw).
]]
local options = {"show", "highlight", "style", "layout", "causality"}
local bgdraw = os.getenv("BGDRAW") or "bgdraw"

local function draw(text, attrs, fmt)
  local args = {"-", "-T", fmt, "-q"}
  for _, key in ipairs(options) do
    if attrs[key] then
      table.insert(args, "--" .. key)
      table.insert(args, attrs[key])
    end
  end
  local ok, out = pcall(pandoc.pipe, bgdraw, args, text)
  if not ok then
    io.stderr:write("bgdraw filter: " .. tostring(out.output or out) .. "\n")
    error("bgdraw could not draw a ```bgdraw block")
  end
  return out
end

function CodeBlock(block)
  if not block.classes:includes("bgdraw") then return nil end
  local attrs = block.attributes
  if FORMAT:match("html") then
    local svg = draw(block.text, attrs, "svg")
    svg = svg:sub((svg:find("<svg", 1, true))) -- no XML declaration inside HTML
    return pandoc.RawBlock("html", '<div class="bgdraw">' .. svg .. "</div>")
  end
  local fmt = (FORMAT:match("latex") or FORMAT:match("beamer")) and "pdf" or "svg"
  local data = draw(block.text, attrs, fmt)
  local name = "bgdraw-" .. pandoc.utils.sha1(block.text .. fmt) .. "." .. fmt
  pandoc.mediabag.insert(name, fmt == "pdf" and "application/pdf" or "image/svg+xml", data)
  local caption = attrs.caption and {pandoc.Str(attrs.caption)} or {}
  return pandoc.Para({pandoc.Image(caption, name)})
end
