"""Arrays in any layout numpy makes are read, not refused by the engine's binding: views with
negative or zero strides, size-1 axes flipped (numpy calls np.ones((1, 3))[::-1] C-contiguous
though its row stride is negative), transposes, every-other-pixel slices, read-only arrays."""

import numpy as np
import pytest

import seaway
from seaway.chart.raster import engine_layout

CASES = {
    "flipped size-1 rows": lambda a: a[:1][::-1],
    "flipped size-1 columns": lambda a: a[:, :1][:, ::-1],
    "flipped rows": lambda a: a[::-1],
    "flipped both": lambda a: a[::-1, ::-1],
    "transposed": lambda a: a.T,
    "every other column": lambda a: a[:, ::2],
    "broadcast row": lambda a: np.broadcast_to(a[:1], a.shape),
    "read-only": lambda a: _read_only(a),
    "fortran order": lambda a: np.asfortranarray(a),
}


def _read_only(a):
    b = a.copy()
    b.flags.writeable = False
    return b


@pytest.mark.parametrize("name", list(CASES))
def test_every_layout_routes_like_a_plain_copy(name):
    base = np.random.default_rng(4).uniform(1.0, 3.0, (4, 6))
    view = CASES[name](base)
    plain = np.array(view, order="C")
    end = (view.shape[0] - 1, view.shape[1] - 1)
    land_view = CASES[name](np.zeros(base.shape, bool))
    r, p = seaway.route(view, (0, 0), end, land=land_view), seaway.route(plain, (0, 0), end)
    assert r.cost == p.cost and np.array_equal(r.pixels, p.pixels)
    np.testing.assert_array_equal(seaway.cost_field(view, (0, 0)), seaway.cost_field(plain, (0, 0)))
    assert seaway.prepare(view, land=land_view).route((0, 0), end).cost == p.cost


def test_the_issue_reproducers_route():
    """seaway.route(np.ones((1, 3))[::-1], (0, 0), (0, 2)) raised pybind11's "incompatible
    function arguments"; cost_field and prepare the same."""
    flipped = np.ones((1, 3))[::-1]
    assert flipped.flags.c_contiguous and flipped.strides[0] < 0
    assert seaway.route(flipped, (0, 0), (0, 2)).cost == 2.0
    assert seaway.cost_field(flipped, (0, 0)).tolist() == [[0.0, 1.0, 2.0]]
    assert seaway.prepare(flipped).route((0, 2), (0, 0)).cost == 2.0


def test_plain_arrays_are_read_in_place_and_odd_ones_copied_once():
    plain = np.ones((3, 4))
    assert engine_layout(plain) is plain
    odd = engine_layout(np.ones((1, 4))[::-1])
    assert odd.strides == (32, 8) and odd.flags.owndata
