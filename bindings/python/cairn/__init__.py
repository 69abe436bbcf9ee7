"""Cairn from Python: block diagrams, mathematical programs, multibody algorithms, perception and planning.

The submodules mirror the C++ folders: cairn.systems, cairn.optimization, cairn.multibody, cairn.perception,
cairn.planning, cairn.visualization (and cairn.examples, the example systems). Everything is implemented in C++
(the extension module cairn._cairn); numpy arrays cross without copies where the memory layouts agree (see README,
"Using Cairn from Python").
"""

import os as _os
import sys as _sys

from . import _cairn
from ._build_info import __version__, _SOURCE_DATA_DIR

systems = _cairn.systems
optimization = _cairn.optimization
multibody = _cairn.multibody
perception = _cairn.perception
planning = _cairn.planning
visualization = _cairn.visualization
examples = _cairn.examples

# `import cairn.systems` and pickling (which imports a class's __module__, cairn._cairn.<name>) need the
# submodules in sys.modules under both names.
for _name in ("systems", "optimization", "multibody", "perception", "planning", "visualization", "examples"):
    _module = getattr(_cairn, _name)
    _sys.modules[__name__ + "." + _name] = _module
    _sys.modules[__name__ + "._cairn." + _name] = _module


def data_dir():
    """The folder of the project's data (robots/, models/): $CAIRN_DATA_DIR, else the source tree's data/ folder
    this module was built from, or None when neither exists (the data is not installed with the module)."""
    for folder in (_os.environ.get("CAIRN_DATA_DIR"), _SOURCE_DATA_DIR):
        if folder and _os.path.isdir(folder):
            return folder
    return None


__all__ = ["systems", "optimization", "multibody", "perception", "planning", "visualization", "examples", "data_dir", "__version__"]
