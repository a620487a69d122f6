"""A table file's raw text: its rows as strings (UTF-8, the delimiter sniffed from the header, a line number per
row) and a cell as a number (a decimal comma, a Unicode minus and unusable numbers each one clear line).  The
first stage of :func:`demid.data.read_table`."""

from __future__ import annotations

import csv
import io
import re
from pathlib import Path

from .errors import InputError
from .numbers import unusable_number

UNICODE_MINUS = "\u2212"
_DECIMAL_COMMA = re.compile(r"^[+-]?\d*,\d+$")
_THOUSANDS_OR_DECIMAL = re.compile(r"^[+-]?[1-9]\d{0,2},\d{3}$")
_LINE_BREAK = re.compile(r"\r\n|\r|\n")


def _sniff_delimiter(header: str) -> str:
    counts = {d: header.count(d) for d in (",", ";", "\t")}
    return max(counts, key=lambda d: (counts[d], d == ","))


def read_raw_numbered(path: Path | str) -> tuple[list[str], list[list[str]], list[int]]:
    """Header, string cells and each row's line number in the file (comment and blank lines skipped)."""
    path = Path(path)
    if not path.is_file():
        raise InputError("data file does not exist", source=str(path))
    text = _table_text(path)
    numbered = _records(text)
    if not numbered:
        raise InputError("the file is empty", source=str(path))
    delim = _sniff_delimiter(numbered[0][1])
    rows = []
    for no, record in numbered:
        try:
            rows.append(next(csv.reader(io.StringIO(record, newline=""), delimiter=delim)))
        except csv.Error as exc:  # e.g. a cell beyond the csv module's field size limit
            raise InputError(f"line {no}: not readable as CSV ({exc})", source=str(path)) from None
    header, rows = _drop_trailing_empty_columns([h.strip() for h in rows[0]], rows[1:])
    return header, rows, [no for no, _ in numbered[1:]]


def _table_text(path: Path) -> str:
    """A table file's text: UTF-8 (a BOM dropped); other encodings raise InputError naming the file."""
    data = path.read_bytes()
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise InputError(f"not UTF-8 text (byte {exc.start}); save the table as UTF-8 CSV", source=str(path)) from None
    if "\0" in text:  # valid UTF-8, yet no text table holds NUL: UTF-16 without a byte-order mark writes one per letter
        raise InputError(f"not UTF-8 text (a NUL byte at byte {data.index(0)}: UTF-16 without a byte-order mark?); "
                         "save the table as UTF-8 CSV", source=str(path))
    return text


def _lines(text: str) -> list[str]:
    """The text's lines, broken where CSV breaks them (\\n, \\r\\n, \\r) only: str.splitlines also breaks
    at U+2028, U+0085 and form feeds, which are text inside a cell."""
    lines = _LINE_BREAK.split(text)
    return lines[:-1] if lines and lines[-1] == "" else lines


def _records(text: str) -> list[tuple[int, str]]:
    """(first line number, text) of each CSV record, comment and blank lines skipped.  A quoted cell may
    hold a line break (valid CSV): its record continues on the next lines until the quote closes; a quote
    never closed leaves every line its own record (the cell count then names the line)."""
    lines = _lines(text)
    out: list[tuple[int, str]] = []
    no = 0
    while no < len(lines):
        line = lines[no]
        if not line.strip() or line.lstrip().startswith("#"):
            no += 1
            continue
        end, quotes = no, line.count('"')
        while quotes % 2 and end + 1 < len(lines):
            end += 1
            quotes += lines[end].count('"')
        if quotes % 2:  # unclosed to the end of the file
            end = no
        out.append((no + 1, "\n".join(lines[no:end + 1])))
        no = end + 1
    return out


def _drop_trailing_empty_columns(header: list[str], rows: list[list[str]]) -> tuple[list[str], list[list[str]]]:
    """Spreadsheets often export empty columns after the last one used (``run,a,b,,``): columns at the end
    with no name and no value in any row are not part of the table."""
    width = len(header)
    while width and header[width - 1] == "" and all(len(r) < width or not r[width - 1].strip() for r in rows):
        width -= 1
    if width == len(header):
        return header, rows
    # a row with a value beyond the header keeps its length, so that its cell count is refused as before
    return header[:width], [r[:width] if not any(c.strip() for c in r[width:]) else r for r in rows]


def read_raw(path: Path | str) -> tuple[list[str], list[list[str]], str]:
    """Header and string cells; a UTF-8 BOM is dropped, delimiter sniffed from the header."""
    header, rows, _ = read_raw_numbered(path)
    lines = _lines(_table_text(Path(path)))
    first = next(ln for ln in lines if ln.strip() and not ln.lstrip().startswith("#"))
    return header, rows, _sniff_delimiter(first)


def parse_number(cell: str) -> float:
    """Parse one cell; Unicode minus is accepted.  Raises ValueError with a readable reason."""
    s = cell.strip().replace(UNICODE_MINUS, "-")
    if s == "":
        raise ValueError("empty cell")
    if _THOUSANDS_OR_DECIMAL.match(s):
        raise ValueError(f"found '{cell.strip()}': a thousands separator ({s.replace(',', '')}) or a decimal "
                         f"comma ({s.replace(',', '.')})? write the number with a decimal point and no separator")
    if _DECIMAL_COMMA.match(s):
        raise ValueError(f"found '{cell.strip()}', a decimal comma; expected a decimal point, e.g. "
                         f"'{s.replace(',', '.')}'")
    if "_" in s:  # Python reads 1_29.3 as 129.3; a table cell with an underscore is a slip
        raise ValueError(f"found '{cell.strip()}', a number with an underscore; expected digits only")
    try:
        value = float(s)
    except ValueError:
        raise ValueError(f"found '{cell.strip()}', expected a number") from None
    problem = unusable_number(value, cell) if s.lower().lstrip("+-") not in ("nan", "inf", "infinity") else ""
    if problem:  # spelled-out nan/inf keep their meaning (a failed run) to the caller
        raise ValueError(problem)
    return value


def is_number(text: str) -> bool:
    try:
        parse_number(text)
    except ValueError:
        return False
    return True
