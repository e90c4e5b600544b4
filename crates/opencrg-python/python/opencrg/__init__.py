"""OpenCRG road surfaces: the reference C library's answers, numpy-vectorised, on a Rust core."""

from .opencrg import *  # noqa: F401,F403 (the native module's classes and functions)
from .opencrg import __doc__, __version__, odr  # noqa: F401
