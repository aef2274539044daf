r"""What a run can compute: the precision left in a phase, and the memory and steps it needs.

**Phase precision.** Every solution of the rotation carries phases ``ω t`` (the attitude
turns about the angular momentum, ``m(t)`` runs round its polhode). A time ``t`` and the
frequency ``ω`` are float64 numbers, each known to half an ulp (relative ``2⁻⁵³``): the
phase is then uncertain by about

.. math:: \delta = |\omega t| \, 2^{-52} \ \text{rad},

however exactly it is computed afterwards (the exact flow reduces it in double-double:
the error is the input's). The decimal digits left in the phase (in radians) are
``−log₁₀ δ``. :func:`check_phase` warns (:class:`PhasePrecisionWarning`) once fewer than
:data:`PHASE_WARN_DIGITS` = 6 digits are left, ``|ω t| > 10⁻⁶ · 2⁵² ≈ 4.5·10⁹`` rad
(7·10⁸ turns), and raises :class:`ValueError` once none is left, ``|ω t| ≥ 2⁵² ≈ 4.5·10¹⁵``
rad (7·10¹⁴ turns): the state printed there would be any point of its orbit. The rate
used is :func:`spin_rate`, ``|m| / min(I)``, a bound on every phase rate of the free
motion (the angular velocity, the polhode frequency ``2π/T`` and the precession rate).

**Sizes.** :func:`check_size` refuses, before anything is allocated, a run that needs
more memory than it may still take (:func:`memory_limit`: the least of the physical
memory, what ``ulimit -v`` leaves above the address space in use, and what a control
group's memory limit leaves above its use) or longer than :data:`MAX_STEPS` elementary
steps (a state's Strang substep), about 3.6 hours at the compiled splitting's measured
1.3 µs (slower steps, e.g. DOP853's, count for their measured cost; work measured in
seconds counts as such); the message gives what the request would need. Every command's
estimate is an upper bound of what it allocates, so that a request accepted here does not
fail later for want of memory.

**Long runs.** :func:`progress` shows a progress bar on standard error for long runs when
the command line asked for it (:func:`show_progress`), on a terminal; :func:`announce` says
once, on standard error whether or not it is a terminal, that a run estimated past
:data:`ANNOUNCE_SECONDS` starts, how long it should take and where its work is kept. A run
stopped by Ctrl-C (SIGINT) that kept part of its work raises :class:`Interrupted` (a
:class:`KeyboardInterrupt`) saying what it kept; the command line prints that one line and
exits with status 130.
"""

from __future__ import annotations

import math
import os
import sys
import warnings
from collections.abc import Iterator
from contextlib import contextmanager, nullcontext
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

__all__ = [
    "ANNOUNCE_SECONDS",
    "MAX_STEPS",
    "PHASE_ERROR_LIMIT",
    "PHASE_WARN_DIGITS",
    "PHASE_WARN_LIMIT",
    "STEP_SECONDS",
    "Interrupted",
    "PhasePrecisionWarning",
    "ToleranceWarning",
    "announce",
    "caller_stacklevel",
    "check_phase",
    "check_size",
    "check_spin_phase",
    "format_bytes",
    "format_duration",
    "memory_limit",
    "progress",
    "show_progress",
    "spin_bound",
    "spin_rate",
]

#: Decimal digits of the phase (radians) below which :func:`check_phase` warns.
PHASE_WARN_DIGITS = 6
#: ``|ω t|`` (rad) past which the phase keeps fewer than ``PHASE_WARN_DIGITS`` digits: ``10⁻⁶ · 2⁵²``.
PHASE_WARN_LIMIT = 10.0**-PHASE_WARN_DIGITS * 2.0**52
#: ``|ω t|`` (rad) from which no digit of the phase is left: an error of one radian, ``2⁵²``.
PHASE_ERROR_LIMIT = 2.0**52
#: Seconds of one elementary step: a Strang substep of one state in the compiled splitting
#: (measured 1.3 µs on a loaded 2-core machine; ``andoyer.integrate.splitting``).
STEP_SECONDS = 1.3e-6
#: Most elementary steps of one run (states × substeps): about 3.6 hours at ``STEP_SECONDS``.
MAX_STEPS = 10**10
#: Estimated seconds of work past which :func:`announce` tells the command line's user.
ANNOUNCE_SECONDS = 10.0

_PACKAGE = str(Path(__file__).resolve().parent)
_NO_CONTEXT = nullcontext()


class Interrupted(KeyboardInterrupt):
    """A run stopped by Ctrl-C (SIGINT); its message says, in one line, what was kept.

    A :class:`KeyboardInterrupt`, so that code catching those still does. The command line
    prints ``andoyer COMMAND: interrupted; MESSAGE`` and exits with status 130.

    Examples
    --------
    >>> str(Interrupted("kept 1.2 Myr of the orbit in /tmp/cache"))
    'kept 1.2 Myr of the orbit in /tmp/cache'
    """


class PhasePrecisionWarning(UserWarning):
    """A phase ``ω t`` so large that fewer than :data:`PHASE_WARN_DIGITS` digits of it are left.

    Raised as a warning (the numbers are still those of the float64 inputs, but a change
    of one ulp in ``t`` or in the moments moves them); see :func:`check_phase`.
    """


class ToleranceWarning(UserWarning):
    """A requested accuracy that a run could not reach: its result reports the error it estimates.

    Issued by the runs that choose their step from a tolerance (the spin axis' histories, the
    splitting) when the step they may take runs out before the estimate meets the request.
    """


def caller_stacklevel() -> int:
    """The ``stacklevel`` that points a warning issued by the caller of this function at user code.

    Counts the frames from that caller up to the first one outside the ``andoyer``
    package (the command line counts as inside: its warnings point at its entry).

    Examples
    --------
    >>> caller_stacklevel() >= 1
    True
    """
    frame = sys._getframe(1)
    level = 1
    while frame.f_back is not None and str(Path(frame.f_code.co_filename).resolve()).startswith(_PACKAGE):
        frame = frame.f_back
        level += 1
    return level


def spin_rate(moments: ArrayLike, m: ArrayLike) -> float:
    """The fastest phase rate of the free motion of states ``m`` (..., 3): ``max |m| / min(I)``.

    It bounds the angular velocity ``|I⁻¹ m|``, the precession rate of the attitude about
    the angular momentum and the polhode frequency ``2π/T``, all at most ``|m|/min(I)``.

    Parameters
    ----------
    moments : array_like, shape (..., 3)
    m : array_like, shape (..., 3)
        Body angular momenta.

    Returns
    -------
    float
        Radians per unit time (``0.0`` for no state).

    Examples
    --------
    >>> spin_rate([1.0, 2.0, 4.0], [[0.0, 0.0, 2.0], [3.0, 0.0, 4.0]])
    5.0
    """
    moments = np.asarray(moments, dtype=np.float64)
    m = np.asarray(m, dtype=np.float64)
    if m.size == 0 or moments.size == 0:
        return 0.0
    # scaled by the largest component, so that no square overflows (this runs on every free flow)
    largest = float(np.max(np.abs(m)))
    if largest == 0.0:
        return 0.0
    u = m / largest
    smallest = np.min(moments, axis=-1)
    with np.errstate(over="ignore") if float(np.min(smallest)) < 1e-300 else _NO_CONTEXT:
        rate = np.max(np.sqrt(np.sum(u * u, axis=-1)) / smallest)
    return largest * float(rate)  # a Python float: an overflow is inf, without a warning


def check_phase(rate: float, t: ArrayLike, what: str = "the motion") -> None:
    """Check that the phases ``rate · t`` keep digits: warn past ``PHASE_WARN_LIMIT``, refuse past ``2⁵²``.

    Parameters
    ----------
    rate : float
        The fastest phase rate, radians per unit time (e.g. :func:`spin_rate`).
    t : array_like
        Times since the state (spans), any shape.
    what : str
        What is propagated, for the message.

    Raises
    ------
    ValueError
        Once ``|rate · t| ≥ 2⁵²``: the phase error ``|ω t| 2⁻⁵²`` reaches a radian.

    Warns
    -----
    PhasePrecisionWarning
        Once ``|rate · t| > 10⁻⁶ · 2⁵²``: fewer than six digits of the phase are left.

    Examples
    --------
    >>> check_phase(1.0, [0.0, 1e9])  # 1e9 rad: 7 digits left, quiet
    >>> check_phase(1.0, 1e17)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: expected times with |ω t| below 4.5e+15 rad so that the phase ... got |ω t| = 1e+17 rad ...
    """
    t = np.asarray(t, dtype=np.float64)
    if t.size == 0 or not rate > 0:
        return
    span = float(np.max(np.abs(t)))
    phase = abs(rate) * span  # Python floats: an overflow is inf, refused below
    detail = f"|ω t| = {phase:.3g} rad (ω = {rate:.3g} rad per unit time, |t| = {span:.3g})"
    if phase >= PHASE_ERROR_LIMIT:
        msg = (
            f"expected times with |ω t| below {PHASE_ERROR_LIMIT:.2g} rad so that the phase of {what} "
            f"keeps at least one digit, got {detail}"
        )
        raise ValueError(msg)
    if phase > PHASE_WARN_LIMIT:
        digits = -math.log10(phase * 2.0**-52)
        msg = (
            f"the phase of {what} keeps only {digits:.1f} digits: {detail}, an error of about "
            f"{phase * 2.0**-52:.1g} rad from the float64 rounding of t and ω"
        )
        warnings.warn(PhasePrecisionWarning(msg), stacklevel=caller_stacklevel())


def spin_bound(moments: ArrayLike, m: ArrayLike) -> float:
    """A cheap upper bound of :func:`spin_rate`: ``√3 max|mᵢ| / min(I)`` (a Python float, ``inf`` past range).

    Examples
    --------
    >>> spin_bound([1.0, 2.0, 4.0], [[0.0, 0.0, 2.0], [3.0, 0.0, 4.0]]) >= 5.0
    True
    """
    m, moments = np.asarray(m, dtype=np.float64), np.asarray(moments, dtype=np.float64)
    if m.size == 0 or moments.size == 0:
        return 0.0
    # the methods skip np.max's dispatch; Python floats overflow to inf without a warning
    return 1.7320508075688772 * float(abs(m).max()) / float(moments.min())


def check_spin_phase(
    moments: ArrayLike, m: ArrayLike, t: ArrayLike, what: str = "the motion", bound: float | None = None
) -> None:
    """:func:`check_phase` at the :func:`spin_rate` of states ``m`` (..., 3) of a body ``moments``.

    The exact rate is computed only where :func:`spin_bound` (or ``bound``, the caller's
    cached value) does not already put the phase below the warning: the free flow runs
    this on every call, often for one state.

    Examples
    --------
    >>> check_spin_phase([1.0, 2.0, 3.0], [0.0, 0.0, 2.0], [0.0, 1e3])
    """
    t = np.asarray(t, dtype=np.float64)
    if t.size == 0:
        return
    if bound is None:
        bound = spin_bound(moments, m)
    if bound * float(abs(t).max()) <= PHASE_WARN_LIMIT:
        return
    check_phase(spin_rate(moments, m), t, what)


def _address_space() -> int:
    """Bytes of address space this process maps now (``/proc/self/statm``; 0 where unknown)."""
    try:
        with open("/proc/self/statm", encoding="ascii") as statm:
            return int(statm.read().split()[0]) * int(os.sysconf("SC_PAGE_SIZE"))
    except (OSError, ValueError, IndexError, AttributeError):
        return 0


def _read_number(path: str) -> int | None:
    try:
        with open(path, encoding="ascii") as f:
            text = f.read().strip()
    except OSError:
        return None
    return int(text) if text.isdigit() else None


def _cgroup_room() -> int | None:
    """What the memory limit of this process's control group leaves above its use (``None``: no limit).

    cgroup v2 (``memory.max`` less ``memory.current``) or v1 (``memory.limit_in_bytes`` less
    ``memory.usage_in_bytes``), at the group ``/proc/self/cgroup`` names, else at the root of
    the mount (a container sees its own group there).
    """
    try:
        with open("/proc/self/cgroup", encoding="ascii") as f:
            lines = f.read().splitlines()
    except OSError:
        return None
    rooms = []
    for line in lines:
        _, controllers, path = [*line.split(":", 2), "", ""][:3]
        if controllers == "":
            files = ("/sys/fs/cgroup{}/memory.max", "/sys/fs/cgroup{}/memory.current")
        elif "memory" in controllers.split(","):
            v1 = "/sys/fs/cgroup/memory{}/memory."
            files = (v1 + "limit_in_bytes", v1 + "usage_in_bytes")
        else:
            continue
        for where in dict.fromkeys((path.rstrip("/"), "")):
            limit, used = (_read_number(name.format(where)) for name in files)
            if limit is not None:
                rooms.append(limit - (used or 0))
                break
    return min(rooms) if rooms else None


def memory_limit() -> int:
    """Bytes one run may still allocate.

    The least of the machine's physical memory (``SC_PHYS_PAGES · SC_PAGE_SIZE``, 16 GiB where
    the operating system does not say), what the address-space limit (``ulimit -v``,
    ``RLIMIT_AS``) leaves above the address space this process maps now, and what the memory
    limit of its control group leaves above the group's use.

    Examples
    --------
    >>> memory_limit() > 2**20
    True
    """
    try:
        limits = [int(os.sysconf("SC_PHYS_PAGES")) * int(os.sysconf("SC_PAGE_SIZE"))]
    except (AttributeError, ValueError, OSError):
        limits = [16 * 2**30]
    try:
        import resource

        soft = resource.getrlimit(resource.RLIMIT_AS)[0]
        if soft != resource.RLIM_INFINITY:
            limits.append(soft - _address_space())
    except (ImportError, OSError, ValueError):
        pass
    room = _cgroup_room()
    if room is not None:
        limits.append(room)
    return max(0, min(limits))


def format_bytes(n: float) -> str:
    """A byte count with a binary prefix.

    Examples
    --------
    >>> format_bytes(8e15), format_bytes(512)
    ('7.11 PiB', '512 B')
    """
    units = ("B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB", "ZiB", "YiB")
    k = 0
    while n >= 1024 and k < len(units) - 1:
        n /= 1024
        k += 1
    return f"{n:.0f} {units[k]}" if k == 0 else f"{n:.3g} {units[k]}"


def format_duration(seconds: float) -> str:
    """A duration in the largest unit that keeps it above one.

    Examples
    --------
    >>> format_duration(42.0), format_duration(754.0), format_duration(3.6 * 3600), format_duration(4e5)
    ('42 s', '13 minutes', '3.6 hours', '4.6 days')
    """
    if not seconds < 3600 * 24 * 365.25 * 1e6:  # also NaN
        return f"{seconds / (3600 * 24 * 365.25):.2g} years"
    if seconds < 99.5:
        return f"{seconds:.0f} s"
    if seconds < 3600 * 1.5:
        return f"{seconds / 60:.0f} minutes"
    if seconds < 86400 * 1.5:
        return f"{seconds / 3600:.2g} hours"
    return f"{seconds / 86400:.2g} days"


def check_size(
    what: str,
    steps: float = 0.0,
    nbytes: float = 0.0,
    step_seconds: float = STEP_SECONDS,
    seconds: float = 0.0,
) -> None:
    """Refuse, before it starts, a run of ``steps`` steps (or ``seconds``) allocating ``nbytes`` bytes.

    Parameters
    ----------
    what : str
        The run, for the message (e.g. ``"a splitting run"``).
    steps : float
        Elementary steps (states × steps).
    nbytes : float
        Bytes it would allocate; at most :func:`memory_limit`.
    step_seconds : float
        Measured seconds per step (default :data:`STEP_SECONDS`); ``steps · step_seconds``
        is at most :data:`MAX_STEPS` ``·`` :data:`STEP_SECONDS` (about 3.6 hours).
    seconds : float
        Estimated seconds of work not counted in steps (added to ``steps · step_seconds``).

    Raises
    ------
    ValueError
        Naming the limit and what the request would need.

    Examples
    --------
    >>> check_size("a test", steps=1e3, nbytes=8e3)
    >>> check_size("a test", nbytes=8e15)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: expected a test of at most ... of memory, got one that would need 7.11 PiB
    >>> check_size("a test", steps=1e15)  # doctest: +NORMALIZE_WHITESPACE
    Traceback (most recent call last):
    ...
    ValueError: expected a test of at most 1e+10 steps (about 3.6 hours),
    got 1e+15 steps (about 3.6e+05 hours)
    >>> check_size("a test", seconds=7.2e4)
    Traceback (most recent call last):
    ...
    ValueError: expected a test of at most about 3.6 hours, got one of about 20 hours
    """
    limit = memory_limit()
    if not nbytes <= limit:
        msg = (
            f"expected {what} of at most {format_bytes(limit)} of memory, "
            f"got one that would need {format_bytes(nbytes)}"
        )
        raise ValueError(msg)
    budget = MAX_STEPS * STEP_SECONDS
    if seconds and not steps * step_seconds + seconds <= budget:
        total = steps * step_seconds + seconds
        msg = (
            f"expected {what} of at most about {budget / 3600:.2g} hours, "
            f"got one of about {format_duration(total)}"
        )
        raise ValueError(msg)
    if not steps * step_seconds <= budget:
        msg = (
            f"expected {what} of at most {budget / step_seconds:.2g} steps "
            f"(about {budget / 3600:.2g} hours), "
            f"got {steps:.3g} steps (about {steps * step_seconds / 3600:.2g} hours)"
        )
        raise ValueError(msg)


_SHOW: dict[str, Any] = {"enabled": False, "prefix": "andoyer"}


@contextmanager
def show_progress(enabled: bool = True, prefix: str = "andoyer") -> Iterator[None]:
    """Let :func:`progress` and :func:`announce` speak (on standard error) inside this block.

    The command line turns it on, with ``prefix`` its name (``andoyer obliquity``); library
    calls stay silent.

    Examples
    --------
    >>> with show_progress(), progress(10, "demo") as bar:  # drawn on a terminal only
    ...     if bar is not None:
    ...         _ = bar.update(10)
    """
    before = dict(_SHOW)
    _SHOW.update(enabled=enabled, prefix=prefix)
    try:
        yield
    finally:
        _SHOW.update(before)


def announce(
    seconds: float, what: str, where: str | os.PathLike[str] | None = None, stream: Any = None
) -> bool:
    r"""Say once, on ``stream`` (standard error), that a run of about ``seconds`` starts.

    Only inside :func:`show_progress` (the command line) and only for runs estimated past
    :data:`ANNOUNCE_SECONDS`; unlike a progress bar, also when standard error is not a
    terminal (a log file, a batch job), so that a long wait is never silent.

    Parameters
    ----------
    seconds : float
        The estimate.
    what : str
        The work, e.g. ``"integrating 12 Myr of the Solar System"``.
    where : str or path-like, optional
        Where its result is kept (a cache folder).
    stream : file, optional
        Default ``sys.stderr``.

    Returns
    -------
    bool
        Whether it spoke.

    Examples
    --------
    >>> import io
    >>> out = io.StringIO()
    >>> with show_progress(prefix="andoyer demo"):
    ...     announce(754.0, "integrating 9 Myr of the Solar System", "/tmp/cache", out)
    True
    >>> out.getvalue()
    'andoyer demo: integrating 9 Myr of the Solar System, about 13 minutes (kept in /tmp/cache)\n'
    >>> announce(754.0, "quiet outside the command line", stream=out)
    False
    """
    if not (_SHOW["enabled"] and seconds > ANNOUNCE_SECONDS):
        return False
    stream = sys.stderr if stream is None else stream
    kept = "" if where is None else f" (kept in {os.fspath(where)})"
    print(f"{_SHOW['prefix']}: {what}, about {format_duration(seconds)}{kept}", file=stream, flush=True)
    return True


@contextmanager
def progress(total: float, desc: str, unit: str = "step", stream: Any = None) -> Iterator[Any]:
    """A tqdm progress bar of ``total`` units on ``stream`` (standard error), or ``None``.

    Drawn only inside :func:`show_progress`, on a terminal, and only once the run has
    lasted a second (short runs print nothing); it is removed when the run ends.

    Parameters
    ----------
    total : float
        Units of work.
    desc : str
        Label.
    unit : str
        Name of a unit.
    stream : file, optional
        Default ``sys.stderr``.

    Yields
    ------
    tqdm or None
        A bar (``update(n)``) where one is shown, else ``None``.

    Examples
    --------
    >>> with progress(3, "quiet") as bar:
    ...     print(bar)
    None
    """
    stream = sys.stderr if stream is None else stream
    isatty = getattr(stream, "isatty", None)
    if not (_SHOW["enabled"] and callable(isatty) and isatty()):
        yield None
        return
    from tqdm import tqdm

    bar = tqdm(total=total, desc=desc, unit=unit, file=stream, delay=1.0, leave=False, dynamic_ncols=True)
    try:
        yield bar
    finally:
        bar.close()
