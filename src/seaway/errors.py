"""Exceptions raised by seaway."""


class NoRouteError(ValueError):
    """The end cannot be reached from the start on this chart and stencil."""
