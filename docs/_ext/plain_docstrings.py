"""Render seaway's plain-text docstrings as reStructuredText.

Most of seaway's docstrings follow one plain convention rather than numpydoc sections:

    cost: 2-D numpy array or xarray.DataArray of cost per unit length (>= 0; inf or NaN is
        impassable).
    start, end: (lat, lon) in degrees on geographic charts, (row, col) on planar charts.

Read as reStructuredText, a hanging indent like that is a definition list or a block quote that
ends without a blank line, which docutils warns about (and ``sphinx-build -W`` fails on). This
extension rewrites such docstrings before autodoc parses them: an argument line ("name: text"
or "name, name: text") becomes a bullet with the name in bold, a hanging-indent continuation is
joined to its first line, and a blank line is put wherever an indented block (a list, a literal
block after ``::``, a simple table) ends. Docstrings with numpydoc section underlines are left
to napoleon. Nothing is dropped: the words are the docstring's own.
"""

import re

_ARG = re.compile(r"^([A-Za-z_][\w]*(?:\[[^\]]*\])?(?:, ?[A-Za-z_*][\w]*)*): (\S.*)$")
_BULLET = re.compile(r"^([*+-]|\d+\.|\(\w\)) ")
_BORDER = re.compile(r"^=+( +=+)+$")
_SECTION = re.compile(r"^-{3,}$")
_LONE_STARS = re.compile(r"(?<![*\w`])\*\*(?=\w+\b(?!\*))(?![^\n]*?\w\*\*)")


def _escape(text):
    """Escape "|" (a substitution reference in RST, e.g. in |di|) outside ``literals``."""
    parts = text.split("``")
    for k in range(0, len(parts), 2):
        parts[k] = re.sub(r"(?<!\\)\|", r"\\|", parts[k])
    return "``".join(parts)


def _indent(line):
    return len(line) - len(line.lstrip(" "))


def rewrite(lines):
    """The reStructuredText for one docstring's lines (a new list)."""
    if any(_SECTION.match(l.strip()) for l in lines):
        return list(lines)
    out = []
    i, n = 0, len(lines)
    while i < n:
        line = lines[i]
        text = line.strip()
        if not text:
            out.append("")
            i += 1
            continue
        ind = _indent(line)
        # A simple table (three border lines): shown as it is written, as a literal block, since
        # a cell wider than its column (which plain text allows) is a malformed table in RST.
        if _BORDER.match(text):
            if out and out[-1].strip():
                out.append("")
            out += ["::", ""]
            borders = 0
            while i < n and borders < 3:
                if _BORDER.match(lines[i].strip()):
                    borders += 1
                out.append("    " + lines[i])
                i += 1
            out.append("")
            continue
        # A literal block or a directive: the line, its indented block verbatim, a blank line.
        if text.endswith("::") or text.startswith(".. ") or text.startswith(">>>"):
            out.append(line)
            i += 1
            while i < n and (not lines[i].strip() or _indent(lines[i]) > ind
                             or (text.startswith(">>>") and lines[i].strip())):
                if text.startswith(">>>") and not lines[i].strip():
                    break
                out.append(lines[i])
                i += 1
            out.append("")
            continue
        # A paragraph line and its hanging-indent continuation, joined.
        j = i + 1
        parts = [text]
        bullet = _BULLET.match(text)
        while j < n and lines[j].strip() and _indent(lines[j]) > ind:
            parts.append(lines[j].strip())
            j += 1
        arg = None if bullet else _ARG.match(" ".join(parts))
        if arg:
            # An argument's text may go on at the same indent: it ends at the next argument,
            # list item, blank line or indented block.
            while (j < n and lines[j].strip() and _indent(lines[j]) >= ind
                   and not _ARG.match(lines[j].strip()) and not _BULLET.match(lines[j].strip())
                   and not _BORDER.match(lines[j].strip())):
                parts.append(lines[j].strip())
                j += 1
        joined = " ".join(parts)
        arg = None if bullet else _ARG.match(joined)
        if arg:
            joined = f"* **{arg.group(1)}**: {arg.group(2)}"
            bullet = True
        prev = out[-1] if out else ""
        prev_bullet = bool(prev.strip()) and bool(_BULLET.match(prev.strip()))
        if bullet and prev.strip() and not prev_bullet:
            out.append("")                      # a list starts after a blank line
        if not bullet and prev_bullet:
            out.append("")                      # and ends with one
        out.append(" " * ind + _escape(_LONE_STARS.sub(r"\\*\\*", joined)))
        i = j
    return out


_ATTRIBUTES = {}


def _process(app, what, name, obj, options, lines):
    lines[:] = rewrite(lines)
    if what in ("data", "attribute"):
        _ATTRIBUTES[name] = list(lines)


def _keep_attribute(app, what, name, obj, options, lines):
    """Undo napoleon on a constant's or attribute's docstring: it reads the first line as
    "type: description", but these are prose ("name -> value: meaning")."""
    if what in ("data", "attribute") and name in _ATTRIBUTES:
        lines[:] = _ATTRIBUTES.pop(name)


def setup(app):
    app.connect("autodoc-process-docstring", _process, priority=400)  # before napoleon (500)
    app.connect("autodoc-process-docstring", _keep_attribute, priority=600)  # and after it
    return {"parallel_read_safe": True, "parallel_write_safe": True}
