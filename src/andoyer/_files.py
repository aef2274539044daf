"""Files written atomically, with the modes ``open()`` would give them.

:func:`atomic_replace` is the one way the package writes a file (the command line's
outputs, orbit tables and N-body caches, ensemble stores): a temporary file beside the
target, renamed over it only once it is complete, so a reader never sees a half-written
file and an interrupted write leaves the previous file, if any, and nothing else.

``tempfile.mkstemp`` creates files ``0600`` and ``mkdtemp`` folders ``0700`` whatever the
umask, so a file written as a temporary and renamed into place must be given the mode
``open()`` would have given it: ``0o666 & ~umask`` for files, ``0o777 & ~umask`` for folders.
"""

from __future__ import annotations

import contextlib
import os
import stat
import tempfile
from collections.abc import Iterator
from pathlib import Path

__all__ = ["atomic_replace", "atomic_write_bytes", "current_umask", "new_dir_mode", "new_file_mode"]


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


@contextlib.contextmanager
def atomic_replace(target: str | os.PathLike[str]) -> Iterator[Path]:
    """Yield a temporary path beside ``target``; rename it over ``target`` when the block succeeds.

    The temporary file exists (empty, created by :func:`tempfile.mkstemp` in ``target``'s
    folder, so the rename stays on one file system) when the block starts; the block writes
    it by path. On success it is given the mode of the file it replaces, else
    :func:`new_file_mode`, and renamed over ``target`` (:func:`os.replace`, atomic on POSIX);
    on any exception it is removed and the exception goes on.

    Parameters
    ----------
    target : str or path-like
        The file to write (its folder must exist; a symbolic link is replaced, not followed:
        resolve it first to write through it).

    Yields
    ------
    pathlib.Path
        The temporary file to write.

    Examples
    --------
    >>> folder = Path(tempfile.mkdtemp())
    >>> with atomic_replace(folder / "a.txt") as part:
    ...     _ = part.write_text("done")
    >>> (folder / "a.txt").read_text(), sorted(p.name for p in folder.iterdir())
    ('done', ['a.txt'])
    """
    target = Path(target)
    try:
        mode = stat.S_IMODE(os.stat(target).st_mode)
    except FileNotFoundError:
        mode = new_file_mode()
    fd, name = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".part", dir=target.parent)
    os.close(fd)
    part = Path(name)
    try:
        yield part
        os.chmod(part, mode)  # mkstemp made it 0600 whatever the umask
        os.replace(part, target)
    except BaseException:
        with contextlib.suppress(OSError):
            part.unlink()
        raise


def atomic_write_bytes(target: str | os.PathLike[str], data: bytes) -> None:
    """Write ``data`` to ``target`` through :func:`atomic_replace`.

    Parameters
    ----------
    target : str or path-like
        The file to write.
    data : bytes
        Its whole content.

    Examples
    --------
    >>> path = Path(tempfile.mkdtemp()) / "b.bin"
    >>> atomic_write_bytes(path, b"xy")
    >>> path.read_bytes(), oct(path.stat().st_mode & 0o777) == oct(new_file_mode())
    (b'xy', True)
    """
    with atomic_replace(target) as part:
        part.write_bytes(data)
