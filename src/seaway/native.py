"""seaway.native: the compiled engine (`seaway._core`, built from cpp/ with pybind11), the lowest
layer of the import contract beside seaway.errors. Modules reach the core through this module
(`from .. import native as _core`): the contract's parser sees no extension module, and read
`from .. import _core` as an import of the package itself, which the contract could then only
wave through for every module. Nothing here but the core's names; `_core.pyi` types them."""

from ._core import *  # noqa: F403
