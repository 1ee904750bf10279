"""Finds the compiled module _kessler: on the path (tools/dev.sh writes a .pth file with its folder),
or else in the build folder beside this source tree (build/python), or where KESSLER_BUILD_DIR says."""

import importlib
import os
import sys


def _load():
    try:
        return importlib.import_module("_kessler")
    except ImportError:
        pass
    source = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    build = os.environ.get("KESSLER_BUILD_DIR", os.path.join(source, "build"))
    folder = os.path.join(build, "python")
    if os.path.isdir(folder) and folder not in sys.path:
        sys.path.append(folder)
    try:
        return importlib.import_module("_kessler")
    except ImportError as e:
        raise ImportError(
            f"kessler: the compiled module _kessler is not built (looked in {folder}); build it with "
            "`tools/dev.sh build` (Debian packages pybind11-dev and python3-dev), or set KESSLER_BUILD_DIR "
            f"to the build folder ({e})") from e


_kessler = _load()
