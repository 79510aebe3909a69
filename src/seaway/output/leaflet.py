"""Leaflet in an offline page (folium's elements that would need the network or jQuery,
replaced): Leaflet's own JavaScript and CSS inlined from django-js-lib-leaflet, popups bound
with Leaflet's bindPopup, and a legend that is a Leaflet control, so that Leaflet stacks it with
the other controls of its corner (the scale bar, the attribution) instead of covering them."""

from __future__ import annotations

import base64
import html
import re
from importlib import resources


def leaflet_files():
    """(leaflet.js, leaflet.css with its images as data URLs) from django-js-lib-leaflet."""
    try:
        root = resources.files("js_lib_leaflet") / "static" / "js_lib_leaflet"
        js, css = (root / "leaflet.js").read_text("utf-8"), (root / "leaflet.css").read_text("utf-8")
    except (ModuleNotFoundError, FileNotFoundError):
        raise ImportError(
            'offline HTML maps need Leaflet\'s files: pip install "seaway[plot]" (django-js-lib-leaflet)'
        ) from None

    def inline(match):
        data = (root / match.group(1)).read_bytes()
        return f"url(data:image/png;base64,{base64.b64encode(data).decode('ascii')})"

    return js, re.sub(r"url\((images/[\w.-]+\.png)\)", inline, css)


def inline_leaflet(folium):
    """An element that puts Leaflet itself into the page's <head> (under the names folium uses
    for its CDN links, which the map no longer adds)."""
    from branca.element import Element, MacroElement

    class InlineLeaflet(MacroElement):
        def render(self, **kwargs):
            js, css = leaflet_files()
            head = self.get_root().header
            head.add_child(Element(f"<style>{css}</style>"), name="leaflet_css")
            head.add_child(Element(f"<script>{js}</script>"), name="leaflet")
            super().render(**kwargs)

    return InlineLeaflet()


def popup_element(text: str, max_width: int = 320):
    """A Leaflet popup bound to its parent marker, its HTML given as a string: folium.Popup
    builds its content with jQuery, which an offline page does not load."""
    from branca.element import MacroElement
    from jinja2 import Template

    class Popup(MacroElement):
        _template = Template(
            "{% macro script(this, kwargs) %}"
            "{{ this._parent.get_name() }}.bindPopup({{ this.text|tojson }}, "
            "{maxWidth: {{ this.max_width }}});"
            "{% endmacro %}"
        )

        def __init__(self):
            super().__init__()
            self._name = "Popup"
            self.text, self.max_width = text, int(max_width)

    return Popup()


def legend_control(name, rows, position="bottomright"):
    """A legend box (title `name`, rows [(label, (r, g, b) or None)]) as a Leaflet control in
    `position`: Leaflet stacks it with the corner's other controls, so nothing covers it."""
    from branca.element import MacroElement
    from jinja2 import Template

    items = "".join(
        f'<div><span style="display:inline-block;width:14px;height:10px;'
        f'background:rgb{tuple(rgb)};border:1px solid #444;margin-right:4px"></span>'
        f"{html.escape(label)}</div>"
        if rgb is not None
        else f"<div>{label}</div>"
        for label, rgb in rows
    )
    box = (
        f'<div class="seaway-legend" style="background:white;padding:6px 8px;border:1px solid '
        f'#888;font:12px sans-serif"><b>{html.escape(name)}</b>{items}</div>'
    )

    class Legend(MacroElement):
        _template = Template(
            "{% macro script(this, kwargs) %}"
            "var {{ this.get_name() }} = L.control({position: {{ this.position|tojson }}});"
            "{{ this.get_name() }}.onAdd = function () {"
            " var div = L.DomUtil.create('div'); div.innerHTML = {{ this.box|tojson }};"
            " return div; };"
            "{{ this.get_name() }}.addTo({{ this._parent.get_name() }});"
            "{% endmacro %}"
        )

        def __init__(self):
            super().__init__()
            self._name = "Legend"
            self.box, self.position = box, position

    return Legend()
