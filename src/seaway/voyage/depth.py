"""The depth of an opened chart (seaway.depth): a bathymetry file read and resampled onto the
chart when it is opened (open_chart(depth=...)), the draft enforced when a route is asked for,
a too-shallow end or a missing route explained."""

from __future__ import annotations

import numpy as np

from ..depth import (
    DEFAULT_UKC_SHARE,
    apply_draft,
    check_draft,
    deepest_way,
    depth_on_grid,
    open_bathymetry,
    too_shallow,
)
from ..errors import SeawayError


def read_depth(path, like, *, variable=None, positive=None, crs=None):
    """(depth on the grid of `like` (m, positive down), what was read and assumed, in words)."""
    bathy = open_bathymetry(path, variable=variable, positive=positive)
    depth = depth_on_grid(bathy, like, crs=crs)
    notes = [f"depth from {path}: {bathy.convention}", *bathy.notes]
    notes.append(f"depth resampled onto the chart ({depth.attrs['resampling']})")
    return depth, notes


def with_draft(cost, depth, draft=None, ukc=None, say=None):
    """(cost, reasons(rc) for an end that is too shallow, or None): without a draft the depth is
    only reported; with one, pixels shallower than draft + UKC are closed."""
    say = say or (lambda message: None)
    if depth is None:
        if draft is not None or ukc is not None:
            raise SeawayError(
                "--draft and --ukc need --depth FILE (a bathymetry raster, NetCDF or GeoTIFF, e.g. ETOPO or GEBCO)"
            )
        return cost, None
    if draft is None:
        if ukc is not None:
            raise SeawayError("--ukc needs --draft M (the ship's draft in metres)")
        say("no --draft: the least depth is reported, not enforced")
        return cost, None
    draft, ukc = check_draft(draft, ukc)
    out = apply_draft(cost, depth, draft, ukc)
    z = depth.values
    with np.errstate(invalid="ignore"):
        shallow = int(((z < draft + ukc) & (z > 0)).sum())
    say(
        f"draft {draft:g} m + UKC {ukc:g} m = {draft + ukc:g} m needed: {shallow} water pixels "
        f"too shallow, {int(np.isnan(z).sum())} without depth (impassable)"
    )
    return out, lambda rc: too_shallow(depth, rc, draft, ukc)


def why_no_route(cost, land, depth, start, end, draft, ukc=None) -> str:
    """A sentence for a no-route error with a draft: how deep the deepest way is."""
    given = ukc is not None
    draft, ukc = check_draft(draft, ukc)
    d = deepest_way(cost, land, depth, start, end)
    if d is None:
        return "the ice or land alone keeps the ends apart, whatever the draft"
    most = max(d - ukc, 0.0) if given else d / (1 + DEFAULT_UKC_SHARE)
    return (
        f"the deepest water joining the ends is {d:.1f} m, less than draft {draft:g} m + UKC "
        f"{ukc:g} m = {draft + ukc:g} m: a draft of at most {np.floor(most * 10 + 1e-6) / 10:.1f} m "
        f"({'with this UKC' if given else 'with the default UKC of 10 %'}) gets through"
    )
