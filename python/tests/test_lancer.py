"""The Python module: render to arrays, scene errors, compare, frames, progress, the command,
and a scene written by vapory (a POV-Ray-writing library) rendered through the module and
through the `lancer` command installed as `povray`, with identical pixels. Pictures are tiny:
the tests check plumbing, not the renderer (the Rust tests do that)."""

import os
import shutil
import subprocess
import sys

import numpy as np
import pytest

import lancer

SCENE = """#version 3.7;
global_settings { assumed_gamma 1 }
camera { location -3*z look_at 0 }
light_source { <1, 2, -3> rgb 1 }
sphere { 0, 1 pigment { rgb <1, 0.5, 0.2> } }
"""


def lancer_command():
    """The `lancer` command the package installed beside this Python."""
    exe = os.path.join(os.path.dirname(sys.executable), "lancer")
    return exe if os.path.exists(exe) else shutil.which("lancer")


def test_render_shapes_and_types():
    a = lancer.render(SCENE, width=64, height=48)
    assert a.shape == (48, 64, 3) and a.dtype == np.uint8
    # The sphere's centre is lit, the corner is background.
    assert a[24, 32].sum() > 200 and a[0, 0].sum() == 0
    f = lancer.render(SCENE, width=64, height=48, dtype="float32")
    assert f.shape == (48, 64, 3) and f.dtype == np.float32
    rgba = lancer.render(SCENE, width=16, height=12, options=["+UA"])
    assert rgba.shape == (12, 16, 4) and rgba[0, 0, 3] == 0 and rgba[6, 8, 3] == 255


def test_render_a_path_with_antialiasing(tmp_path):
    p = tmp_path / "s.pov"
    p.write_text(SCENE)
    a = lancer.render(p, width=32, height=24, antialias=0.3)
    b = lancer.render(str(p), width=32, height=24, options=["+A0.3"])
    assert np.array_equal(a, b)


def test_scene_error_has_place():
    with pytest.raises(lancer.SceneError) as e:
        lancer.render("sphere { 0, 1 pigment { rgb 1 }\n", width=8, height=6)
    err = e.value
    assert (err.file, err.line, err.column) == ("<string>", 1, 8)
    assert "never closed" in err.message


def test_compare_arrays_and_files(tmp_path):
    a = lancer.render(SCENE, width=32, height=24)
    assert lancer.compare(a, a) == 1.0
    b = a.copy()
    b[:, :16] = 255
    assert lancer.compare(a, b) < 0.9
    png = tmp_path / "s.png"
    (tmp_path / "s.pov").write_text(SCENE)
    subprocess.run([lancer_command(), "-q", "--no-config", str(tmp_path / "s.pov"),
                    "+W32", "+H24", f"+O{png}"], check=True)
    assert lancer.compare(png, a) == 1.0


def test_frames_and_progress():
    scene = SCENE + "sphere { <clock * 2 - 1, 0, 0>, 0.3 pigment { rgb 1 } }\n"
    seen = list(lancer.frames(scene, width=16, height=12, options=["+KFI1", "+KFF3"]))
    assert [(n, c) for n, c, _ in seen] == [(1, 0.0), (2, 0.5), (3, 1.0)]
    assert not np.array_equal(seen[0][2], seen[2][2])
    calls = []
    lancer.render(SCENE, width=16, height=12, progress=lambda d, t: calls.append((d, t)))
    assert calls and calls[-1] == (12, 12)


def test_the_command_is_installed(tmp_path):
    exe = lancer_command()
    assert exe
    (tmp_path / "s.pov").write_text(SCENE)
    r = subprocess.run([exe, "--no-config", "s.pov", "+W20", "+H10", "-q"], cwd=tmp_path)
    assert r.returncode == 0
    assert (tmp_path / "s.png").exists()


def test_vapory_scene_module_and_command_identical(tmp_path, monkeypatch):
    vapory = pytest.importorskip("vapory")
    camera = vapory.Camera("location", [0, 2, -3], "look_at", [0, 1, 2])
    light = vapory.LightSource([2, 4, -3], "color", [1, 1, 1])
    sphere = vapory.Sphere([0, 1, 2], 2, vapory.Texture(vapory.Pigment("color", [1, 0, 1])))
    box = vapory.Box([-2, -1, 3], [2, 0, 5], vapory.Texture(vapory.Pigment("color", [0.2, 0.8, 0.3])))
    scene = vapory.Scene(camera, objects=[light, sphere, box], included=["colors.inc"])
    # vapory runs `povray` with +O- and Output_File_Type=P and reads the PPM from the pipe:
    # the `lancer` command installed under the name povray takes its place.
    bindir = tmp_path / "bin"
    bindir.mkdir()
    os.symlink(lancer_command(), bindir / "povray")
    monkeypatch.setenv("PATH", f"{bindir}{os.pathsep}{os.environ['PATH']}")
    monkeypatch.setenv("LANCER_NO_CONFIG", "1")
    monkeypatch.chdir(tmp_path)
    by_command = scene.render(width=64, height=48, antialiasing=0.3)
    # render() added the camera's `right` for the aspect ratio; the module renders that text.
    by_module = lancer.render(str(scene), width=64, height=48, antialias=0.3)
    assert by_command.shape == (48, 64, 3)
    assert np.array_equal(by_command, by_module)
    assert by_module[24, 32].sum() > 0
