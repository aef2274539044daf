"""The process's file-creation mask, for files made with :mod:`tempfile` (always private).

``tempfile.mkstemp`` creates files ``0600`` and ``mkdtemp`` folders ``0700`` whatever the
umask, so a file written as a temporary and renamed into place must be given the mode
``open()`` would have given it: ``0o666 & ~umask`` for files, ``0o777 & ~umask`` for folders.
"""

from __future__ import annotations

import os

__all__ = ["current_umask", "new_dir_mode", "new_file_mode"]


def current_umask() -> int:
    """The process's umask, read without changing it where the system allows.

    Linux reports it in ``/proc/self/status`` (``Umask:`` line); elsewhere it is read by
    setting it and putting it back (``os.umask`` has no read-only form).

    Examples
    --------
    >>> old = os.umask(0o027)
    >>> oct(current_umask())
    '0o27'
    >>> _ = os.umask(old)
    """
    try:
        with open("/proc/self/status", encoding="ascii") as status:
            for line in status:
                if line.startswith("Umask:"):
                    return int(line.split()[1], 8)
    except (OSError, ValueError, IndexError):
        pass
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def new_file_mode() -> int:
    """Permission bits of a new regular file, ``0o666 & ~umask`` (what ``open()`` gives).

    Examples
    --------
    >>> old = os.umask(0o022)
    >>> oct(new_file_mode())
    '0o644'
    >>> _ = os.umask(old)
    """
    return 0o666 & ~current_umask()


def new_dir_mode() -> int:
    """Permission bits of a new folder, ``0o777 & ~umask`` (what ``os.mkdir`` gives).

    Examples
    --------
    >>> old = os.umask(0o077)
    >>> oct(new_dir_mode())
    '0o700'
    >>> _ = os.umask(old)
    """
    return 0o777 & ~current_umask()
