"""lancer: a fast ray tracer for POV-Ray 3.7 scenes, linked into Python (no subprocess).

    >>> import lancer
    >>> img = lancer.render("sphere { 0, 1 pigment { rgb 1 } } ...", width=64, height=48)
    >>> img.shape
    (48, 64, 3)

``render`` returns a NumPy array, H x W x 3 (x 4 with ``+UA``), ``uint8`` encoded as the PNG
file would hold it, or ``float32`` linear light. The GIL is released while rendering. Scene
errors raise :class:`SceneError` with ``file``, ``line``, ``column`` and ``message``.
``options`` are the command line's: POV-Ray switches (``+A0.3``, ``+R3``, ``+UA``), INI keys
(``Declare=Size=2``) and INI files. POV-Ray's povray.ini and povray.conf are not read: a call
depends only on its arguments.
"""

from __future__ import annotations

import os
import sys
import warnings as _warnings

import numpy as np

from . import _lancer
from ._lancer import SceneError

__all__ = ["render", "frames", "compare", "SceneError", "main"]


def _scene(scene):
    """(text or path, is_text) for a scene given as SDL text or as a path."""
    if isinstance(scene, os.PathLike):
        return os.fspath(scene), False
    if isinstance(scene, str):
        looks_like_path = "\n" not in scene and "{" not in scene
        if looks_like_path and (os.path.isfile(scene) or scene.endswith(".pov")):
            return scene, False
        return scene, True
    raise TypeError("scene must be SDL text (str) or a path")


def _job(scene, width, height, antialias, options, include_path):
    text, is_text = _scene(scene)
    opts = [f"+W{int(width)}", f"+H{int(height)}"]
    if antialias is not None and antialias is not False:
        opts.append("+A" if antialias is True else f"+A{float(antialias)}")
    opts += [str(o) for o in (options or [])]
    paths = [os.fspath(p) for p in (include_path or [])]
    job = _lancer.prepare(text, is_text, opts, paths)
    for w in job.option_warnings:
        _warnings.warn(w, stacklevel=3)
    return job


def _dtype(dtype):
    d = np.dtype(dtype)
    if d == np.uint8:
        return False
    if d == np.float32:
        return True
    raise ValueError("dtype is uint8 (encoded, as the file holds it) or float32 (linear)")


def _next(job, float_, progress):
    r = job.render_next(float_, progress)
    if r is None:
        return None
    number, clock, picture, warnings = r
    for w in warnings:
        _warnings.warn(w, stacklevel=3)
    return number, clock, picture


def render(scene, width=320, height=240, antialias=None, options=(), include_path=(),
           dtype="uint8", progress=None):
    """Renders a still picture and returns it as a NumPy array.

    scene: SDL text or a path to a .pov file. antialias: None or False for none, a threshold
    (POV-Ray's +A, 0.3 is its default) or True for 0.3. progress: called as
    ``progress(rows_done, rows_total)`` while rendering (from a worker thread).
    """
    job = _job(scene, width, height, antialias, options, include_path)
    return _next(job, _dtype(dtype), progress)[2]


def frames(scene, width=320, height=240, antialias=None, options=(), include_path=(),
           dtype="uint8", progress=None):
    """Renders an animation frame by frame: yields ``(frame_number, clock, picture)``.

    The frames come from the options as on the command line, e.g.
    ``options=["+KFI1", "+KFF24"]`` (Initial_Frame, Final_Frame, +KI/+KF clocks, +KC, +SF/+EF).
    The scene is parsed anew for each frame, as POV-Ray does.
    """
    job = _job(scene, width, height, antialias, options, include_path)
    float_ = _dtype(dtype)
    while True:
        r = _next(job, float_, progress)
        if r is None:
            return
        yield r


def _rgb(x):
    if isinstance(x, (str, os.PathLike)):
        return _lancer.load_rgb(os.fspath(x))
    a = np.asarray(x)
    if a.ndim == 2:
        a = a[:, :, None]
    if a.ndim != 3 or a.shape[2] not in (1, 2, 3, 4):
        raise ValueError(f"expected an H x W (x 1-4) picture, got shape {a.shape}")
    if a.shape[2] in (1, 2):
        a = np.repeat(a[:, :, :1], 3, axis=2)
    a = a[:, :, :3]
    if a.dtype == np.uint8:
        a = a.astype(np.float32) / 255.0
    elif a.dtype == np.uint16:
        a = a.astype(np.float32) / 65535.0
    else:
        a = np.clip(a.astype(np.float32), 0.0, 1.0)
    return np.ascontiguousarray(a, dtype=np.float32)


def compare(a, b):
    """SSIM of two pictures (arrays or file paths) as ``lancer compare`` computes it.

    uint8 and uint16 arrays are scaled to [0, 1], float arrays are clipped to it; alpha is
    dropped and gray replicated, as for files.
    """
    ssim, _psnr, _worst = _lancer.compare_rgb(_rgb(a), _rgb(b))
    return ssim


def main(argv=None):
    """The ``lancer`` command, run in this process."""
    args = list(sys.argv if argv is None else argv) or ["lancer"]
    sys.stdout.flush()
    sys.stderr.flush()
    return _lancer.main(args)


def _console():
    sys.exit(main())
