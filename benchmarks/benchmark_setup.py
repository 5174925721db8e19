"""Shared start of the benchmark scripts: run under Debian's /usr/bin/python3 (where
python3-matplotlib lives) when started by another interpreter, and the repository root."""
import os
import sys


def repository_root():
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        if os.path.exists("/usr/bin/python3") and os.path.realpath(sys.executable) != "/usr/bin/python3":
            os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
    return os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
