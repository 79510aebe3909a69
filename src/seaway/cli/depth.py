"""What `seaway route --depth FILE --draft M [--ukc M]` does with the depth (seaway.depth):
read and resample it, enforce the draft, explain a too-shallow end or a missing route."""

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


def for_route(path, cost, *, draft=None, ukc=None, variable=None, positive=None, say=print, crs=None):
    """What the command line does with --depth/--draft/--ukc: (cost, depth on the cost's grid,
    reasons(rc) for an end that is too shallow). Without a draft the depth is only reported."""
    if path is None:
        if draft is not None or ukc is not None:
            raise ValueError(
                "--draft and --ukc need --depth FILE (a bathymetry raster, NetCDF or "
                "GeoTIFF, e.g. ETOPO or GEBCO)"
            )
        return cost, None, None
    bathy = open_bathymetry(path, variable=variable, positive=positive)
    say(f"depth from {path}: {bathy.convention}")
    for note in bathy.notes:
        say(note)
    depth = depth_on_grid(bathy, cost, crs=crs)
    say(f"depth resampled onto the chart ({depth.attrs['resampling']})")
    if draft is None:
        if ukc is not None:
            raise ValueError("--ukc needs --draft M (the ship's draft in metres)")
        say("no --draft: the least depth is reported, not enforced")
        return cost, depth, None
    draft, ukc = check_draft(draft, ukc)
    out = apply_draft(cost, depth, draft, ukc)
    z = depth.values
    with np.errstate(invalid="ignore"):
        shallow = int(((z < draft + ukc) & (z > 0)).sum())
    say(
        f"draft {draft:g} m + UKC {ukc:g} m = {draft + ukc:g} m needed: {shallow} water pixels "
        f"too shallow, {int(np.isnan(z).sum())} without depth (impassable)"
    )
    return out, depth, lambda rc: too_shallow(depth, rc, draft, ukc)


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
