-- SPDX-License-Identifier: BSD-3-Clause
--[[ pandoc Lua filter: ```bgdraw code blocks become bond graph figures
(docs/integrations.md).

    pandoc doc.md --lua-filter contrib/pandoc/bgdraw.lua -o doc.html
    pandoc doc.md --lua-filter contrib/pandoc/bgdraw.lua --extract-media=media -o doc.tex

    ```{.bgdraw #fig-rlc caption="The series RLC circuit" show=paths}
    Se U = 1
    ...
    ```

    ```{.bgdraw #fig-motor file=models/motor.bg caption="The drive"}
    ```

    As [](#fig-rlc) shows, ...        (an empty link: "Figure 1")

Attributes: the id (#NAME), caption, file (a model file, found as pandoc finds
images: in the working directory, then in --resource-path), alt, and for HTML
align (left, center, right), class (or .CLASS) and format (inline, the SVG in
the page, the default; svg or png, an image), and bgdraw's show, highlight,
style, layout, causality. A block with a caption is
a real figure in every format (HTML <figure>, LaTeX figure with \caption and
\label, docx caption), numbered in order ("Figure 1: ..."; LaTeX numbers
its figures itself); an empty link to its id reads "Figure N" (in LaTeX,
Figure~\ref{id}). LaTeX
gets a PDF, other formats a PNG, kept in pandoc's media bag (give
--extract-media=DIR when the output is not one file).

A model with errors stops the conversion with bgdraw's diagnostics, which
name the Markdown file and the line there (or the model file); an empty
block is an error. BGDRAW in the environment names the program.
]]
local DRAW_OPTIONS = {"show", "highlight", "style", "layout", "causality"}
local KNOWN = {show = 1, highlight = 1, style = 1, layout = 1, causality = 1, caption = 1,
               file = 1, alt = 1, format = 1, name = 1, align = 1, class = 1}
local bgdraw = os.getenv("BGDRAW") or "bgdraw"

-- Stops the conversion with a message, without a Lua stack trace.
local function fail(msg)
  io.stderr:write("bgdraw filter: " .. msg .. "\n")
  os.exit(1)
end

local function is_html() return FORMAT:match("html") ~= nil or FORMAT:match("epub") ~= nil end
local function is_latex() return FORMAT:match("latex") ~= nil or FORMAT:match("beamer") ~= nil end

-- ------------------------------------------------------------ where a block is
local sources = nil -- {name, text} of each input file
local search_from = {} -- per input file: where the next block is looked for

local function read_file(path)
  local f = io.open(path, "rb")
  if not f then return nil end
  local text = f:read("a")
  f:close()
  return (text:gsub("\r\n", "\n"))
end

local function load_sources()
  sources = {}
  for _, name in ipairs(PANDOC_STATE.input_files or {}) do
    local text = name ~= "-" and read_file(name)
    if text then table.insert(sources, {name = name, text = text}) end
  end
end

-- The input file and line of a block's first model line: the block's text
-- found in the inputs, after the blocks found before it. nil when not found
-- (standard input).
local function locate(text)
  if not sources then load_sources() end
  for i, src in ipairs(sources) do
    local at = src.text:find(text, search_from[i] or 1, true)
    if at then
      search_from[i] = at + #text
      local _, newlines = src.text:sub(1, at - 1):gsub("\n", "")
      return src.name, newlines + 1
    end
  end
  return nil
end

-- The file and line of the k-th ```bgdraw fence of the inputs (for an empty
-- block, which has no text to find); nil when the count is off.
local function locate_fence(k)
  if not sources then load_sources() end
  local seen = 0
  for _, src in ipairs(sources) do
    local line = 0
    for text in (src.text .. "\n"):gmatch("([^\n]*)\n") do
      line = line + 1
      if text:match("^%s*[`~][`~][`~]+%s*{?%s*%.?bgdraw[%s}]") or text:match("^%s*[`~][`~][`~]+%s*{?%s*%.?bgdraw$") then
        seen = seen + 1
        if seen == k then return src.name, line end
      end
    end
  end
  return nil
end

-- ------------------------------------------------------------ drawing
local function find_model_file(name)
  local dirs = {"."}
  for _, d in ipairs(PANDOC_STATE.resource_path or {}) do table.insert(dirs, d) end
  if name:sub(1, 1) == "/" then dirs = {""} end
  for _, d in ipairs(dirs) do
    local path = d == "" and name or d == "." and name or d .. "/" .. name
    local f = io.open(path, "r")
    if f then f:close(); return path end
  end
  return nil
end

-- bgdraw's output (format fmt) for a block; stops on a model error (bgdraw
-- has written its diagnostics to stderr).
local function draw(block, attrs, fmt, where)
  local args = {"-q", "-T", fmt}
  for _, key in ipairs(DRAW_OPTIONS) do
    if attrs[key] then table.insert(args, "--" .. key); table.insert(args, attrs[key]) end
  end
  local input = ""
  if attrs.file then
    if block.text:match("%S") then
      fail(where .. ": give file= or write the model in the block, not both")
    end
    local path = find_model_file(attrs.file)
    if not path then fail(where .. ": model file '" .. attrs.file .. "' not found") end
    table.insert(args, 1, path)
  else
    if not block.text:match("%S") then
      fail(where .. ": the ```bgdraw block is empty: write the model in it, or give file=")
    end
    local file, line = locate(block.text)
    table.insert(args, 1, "-")
    table.insert(args, "--stdin-name")
    table.insert(args, file or where)
    -- blank lines before the model: bgdraw's line numbers are the file's
    input = string.rep("\n", (line or 1) - 1) .. block.text .. "\n"
  end
  local ok, out = pcall(pandoc.pipe, bgdraw, args, input)
  if ok then return out end
  if type(out) == "table" and out.error_code then
    fail(where .. ": bgdraw could not draw the model (exit status " .. out.error_code ..
         "; its messages are above)")
  end
  fail(where .. ": cannot run " .. bgdraw .. ": " .. tostring(out))
end

-- ------------------------------------------------------------ figures
local numbers = {} -- figure id -> number
local bg_numbers = {} -- the numbers of the captioned bgdraw blocks, in order
local count = 0    -- blocks seen, for messages when a block is not found

local function bgdraw_attrs(block)
  local attrs = {}
  for k, v in pairs(block.attributes) do
    if not KNOWN[k] then
      local known = {}
      for name in pairs(KNOWN) do table.insert(known, name) end
      table.sort(known)
      fail("unknown ```bgdraw attribute '" .. k .. "' (known: " .. table.concat(known, ", ") .. ")")
    end
    attrs[k] = v
  end
  if block.identifier ~= "" then attrs.name = block.identifier end
  local classes = {attrs.class}
  for _, c in ipairs(block.classes) do
    if c ~= "bgdraw" then table.insert(classes, c) end
  end
  attrs.class = table.concat(classes, " ")
  if attrs.align and not ({left = 1, center = 1, right = 1})[attrs.align] then
    fail("```bgdraw align is left, center or right, not '" .. attrs.align .. "'")
  end
  return attrs
end

local function is_bgdraw(block) return block.t == "CodeBlock" and block.classes:includes("bgdraw") end

local function caption_inlines(attrs)
  if not attrs.caption then return {} end
  local doc = pandoc.read(attrs.caption, "markdown")
  return doc.blocks[1] and doc.blocks[1].content or {}
end

local function figure_html(block, attrs, number, where)
  local fmt = attrs.format or "inline"
  local alt = attrs.alt or attrs.caption or "bond graph"
  local id = (attrs.name and (' id="' .. attrs.name .. '"') or "") ..
             (attrs.align and (' class="align-' .. attrs.align .. '"') or "")
  local div = (attrs.class ~= "" and ("bgdraw " .. attrs.class) or "bgdraw")
  local body
  if fmt == "inline" then
    local svg = draw(block, attrs, "svg", where)
    svg = svg:sub((svg:find("<svg", 1, true))) -- no XML declaration inside HTML
    body = '<div class="' .. div .. '" role="img" aria-label="' .. alt:gsub('"', "&quot;") .. '">' ..
           svg .. "</div>"
  elseif fmt == "svg" or fmt == "png" then
    local data = draw(block, attrs, fmt, where)
    local name = "bgdraw-" .. pandoc.utils.sha1(data) .. "." .. fmt
    pandoc.mediabag.insert(name, fmt == "svg" and "image/svg+xml" or "image/png", data)
    body = '<div class="' .. div .. '"><img src="' .. name .. '" alt="' .. alt:gsub('"', "&quot;") .. '"/></div>'
  else
    fail(where .. ": format is inline, svg or png, not '" .. fmt .. "'")
  end
  if not attrs.caption then
    return {pandoc.RawBlock("html", "<figure" .. id .. ">" .. body .. "</figure>")}
  end
  local caption = {pandoc.Str("Figure " .. number .. ":"), pandoc.Space()}
  for _, x in ipairs(caption_inlines(attrs)) do table.insert(caption, x) end
  return {pandoc.RawBlock("html", "<figure" .. id .. ">" .. body .. "<figcaption>"),
          pandoc.Plain(caption), pandoc.RawBlock("html", "</figcaption></figure>")}
end

local function figure_image(block, attrs, number, where)
  local fmt = is_latex() and "pdf" or "png"
  local data = draw(block, attrs, fmt, where)
  local name = "bgdraw-" .. pandoc.utils.sha1(data) .. "." .. fmt
  pandoc.mediabag.insert(name, fmt == "pdf" and "application/pdf" or "image/png", data)
  local caption = caption_inlines(attrs)
  if attrs.caption and not is_latex() then -- LaTeX numbers its figures itself
    table.insert(caption, 1, pandoc.Space())
    table.insert(caption, 1, pandoc.Str("Figure " .. number .. ":"))
  end
  local attr = pandoc.Attr(attrs.name or "", {"bgdraw"}, {})
  if not attrs.caption then
    return {pandoc.Para({pandoc.Image({pandoc.Str(attrs.alt or "bond graph")}, name, "", attr)})}
  end
  if pandoc.Figure then -- pandoc 3
    return {pandoc.Figure({pandoc.Plain({pandoc.Image(caption, name, "", attr)})}, {pandoc.Plain(caption)}, attr)}
  end
  -- pandoc 2: a paragraph of one image titled "fig:" is a figure
  return {pandoc.Para({pandoc.Image(caption, name, "fig:", attr)})}
end

-- A figure's number: the captioned bgdraw blocks counted in order. LaTeX
-- numbers its figures itself (all of them), and a link there is its \ref.
local function number_figures(doc)
  local n = 0
  doc:walk({
    CodeBlock = function(b)
      if is_bgdraw(b) and b.attributes.caption then
        n = n + 1
        table.insert(bg_numbers, n)
        if b.identifier ~= "" then numbers[b.identifier] = n end
      end
    end,
  })
end

local function draw_blocks(doc)
  local n = 0
  return doc:walk({
    CodeBlock = function(block)
      if not is_bgdraw(block) then return nil end
      count = count + 1
      local attrs = bgdraw_attrs(block)
      if attrs.caption then n = n + 1 end
      local file, line = locate_fence(count)
      if not attrs.file and block.text:match("%S") then
        -- where the block is, for the messages (locate again in draw)
        local saved = {}
        for k, v in pairs(search_from) do saved[k] = v end
        file, line = locate(block.text)
        search_from = saved
      end
      local where = file and (file .. ":" .. line) or ("```bgdraw block " .. count)
      local number = attrs.caption and bg_numbers[n]
      if is_html() then return figure_html(block, attrs, number, where) end
      return figure_image(block, attrs, number, where)
    end,
  })
end

-- An empty link to a bgdraw figure reads "Figure N".
local function fill_links(doc)
  return doc:walk({
    Link = function(link)
      local id = link.target:match("^#(.+)$")
      if not id or not numbers[id] or #link.content > 0 then return nil end
      if is_latex() then return pandoc.RawInline("latex", "Figure~\\ref{" .. id .. "}") end
      link.content = {pandoc.Str("Figure"), pandoc.Space(), pandoc.Str(tostring(numbers[id]))}
      return link
    end,
  })
end

function Pandoc(doc)
  number_figures(doc)
  return fill_links(draw_blocks(doc))
end
