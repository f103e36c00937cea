"""A scratch folder for one test process, removed when the process exits.

Set BOOLSURF_KEEP_TEST_OUTPUT=1 to keep it (the tests print where their pictures are).
"""
import atexit
import os
import shutil
import tempfile


_folders = []


def folder(prefix):
    path = tempfile.mkdtemp(prefix=prefix)
    _folders.append(path)
    return path


@atexit.register
def remove():
    """Removes the folders now; for scripts that end with os._exit, which skips atexit."""
    if not os.environ.get("BOOLSURF_KEEP_TEST_OUTPUT"):
        for path in _folders:
            shutil.rmtree(path, ignore_errors=True)
