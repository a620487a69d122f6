"""The one place report text becomes HTML: Markdown rendered, then cleaned to an allow-list.

Labels, names, units and scenario titles come from a config, and configs come from collaborators:
whatever they hold (``<script>``, ``onerror=`` attributes, ``javascript:`` links, Markdown links) must
reach the reader as text.  Every part of the report passes through :func:`sanitize`: tags outside
:data:`TAGS` are escaped (shown, not run), attributes outside :data:`ATTRIBUTES` dropped, links kept
only to ``http(s)`` addresses or anchors of the page, images only as inline PNG data.
"""

from __future__ import annotations

import re

#: Tags the report's text, tables and figures use.
TAGS = frozenset({
    "a", "b", "blockquote", "br", "code", "del", "em", "figcaption", "figure", "h1", "h2", "h3", "h4", "h5",
    "h6", "hr", "i", "li", "ol", "p", "pre", "strong", "sub", "sup", "table", "tbody", "td", "th", "thead", "tr",
    "ul",
})
#: Figures add their image (``img`` elsewhere, e.g. from a label, is shown as text).
FIGURE_TAGS = TAGS | {"img"}
#: CSS properties the figures set (print size, margins, caption size).
STYLES = frozenset({"width", "max-width", "height", "margin", "font-size", "text-align"})
_PNG_DATA = re.compile(r"data:image/png;base64,[A-Za-z0-9+/=]+")
_PARKED = re.compile(r"demid-image-[0-9]+\Z")
_LINK = re.compile(r"(https?://|#)", re.IGNORECASE)


def _allowed_attribute(tag: str, name: str, value: str) -> bool:
    if name in ("id", "class", "style", "title"):
        return True
    if tag == "a" and name == "href":
        return bool(_LINK.match(value.strip()))
    if tag == "img" and name == "src":
        return bool(_PARKED.match(value))
    if tag == "img" and name == "alt":
        return True
    if tag in ("td", "th") and name == "align":
        return True
    return False


def _cleaner(tags):
    import bleach
    from bleach.css_sanitizer import CSSSanitizer

    return bleach.Cleaner(tags=tags, attributes=_allowed_attribute, protocols={"http", "https"},
                          strip=False, strip_comments=True, css_sanitizer=CSSSanitizer(allowed_css_properties=STYLES))


def sanitize(markup: str, figure: bool = False) -> str:
    """``markup`` with everything outside the allow-list escaped or dropped.  With ``figure`` an image is
    allowed, its source only inline PNG data, which (long, and harmless base64) is set aside while the
    rest is parsed, then put back."""
    images: dict[str, str] = {}

    def park(match: re.Match) -> str:
        key = f"demid-image-{len(images)}"
        images[key] = match.group(0)
        return key

    parked = _PNG_DATA.sub(park, markup) if figure else markup
    clean = _cleaner(FIGURE_TAGS if figure else TAGS).clean(parked)
    for key, data in images.items():
        clean = clean.replace(f'src="{key}"', f'src="{data}"')
    return clean


def markdown_html(text: str) -> str:
    """Markdown rendered as Jupyter renders it (tables, math left for MathJax), then sanitised."""
    from nbconvert.filters.markdown_mistune import markdown2html_mistune

    return sanitize(markdown2html_mistune(text))
