"""One check for the numeric arguments of the public API: a real number (not a string, bool or
array), finite, within bounds; the error names the argument and what to give instead."""

from __future__ import annotations

import numbers

import numpy as np

from ..errors import SeawayError, SeawayTypeError


def number(
    value: object,
    name: str,
    *,
    minimum: float | None = None,
    above: float | None = None,
    maximum: float | None = None,
    integer: bool = False,
    what: str | None = None,
    example: object = None,
) -> float:
    """`value` as a float (int if integer=True), or TypeError (not a number) / ValueError (NaN,
    infinite or out of bounds) whose message names `name`: "{name} must be {what}, got ...".

    minimum: value >= minimum; above: value > above; maximum: value <= maximum."""
    if what is None:
        bounds = [
            f">= {minimum:g}" if minimum is not None else "",
            f"> {above:g}" if above is not None else "",
            f"<= {maximum:g}" if maximum is not None else "",
        ]
        what = " ".join(["a finite " + ("integer" if integer else "number")] + [b for b in bounds if b])
    message = f"{name} must be {what}, got {{}}{value!r}"
    if example is not None:
        message += f"; e.g. {name.split()[0]}={example!r}"
    if isinstance(value, np.ndarray) and value.ndim == 0:
        value = value[()]
    ok_type = numbers.Integral if integer else numbers.Real
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, ok_type):
        raise SeawayTypeError(message.format(type(value).__name__ + " "))
    # mypy narrows value to numbers.Real, whose stub has no __int__; integer=True checked Integral
    v = int(value) if integer else float(value)  # type: ignore[call-overload]
    if not (
        np.isfinite(v)
        and (minimum is None or v >= minimum)
        and (above is None or v > above)
        and (maximum is None or v <= maximum)
    ):
        raise SeawayError(message.format(""))
    return v


def one_line(text: object, limit: int = 200) -> str:
    """`text` on one line, at most `limit` characters, unprintable characters (a damaged
    file's bytes quoted in a library's message) shown as '?': for quoting another library's
    error in seaway's own."""
    text = "".join(c if c.isprintable() else " " if c.isspace() else "?" for c in str(text))
    text = " ".join(text.split())
    return text if len(text) <= limit else text[: limit - 3] + "..."
