"""examples/python/: align.py prints the registration's 4x4, sequence.py
writes a KITTI trajectory of the bundled KITTI frames."""

import os
import subprocess

import numpy as np

import mlndt
from conftest import BUNDLED_DATA_DIR, PYTHON, SOURCE_DIR, reference_transform, translation_error_m

EXAMPLES = SOURCE_DIR / "examples" / "python"


def run_example(name, *arguments, cwd=None):
    completed = subprocess.run(
        [PYTHON, str(EXAMPLES / name), *arguments], capture_output=True, text=True, env=os.environ, cwd=cwd
    )
    return completed


def test_align_prints_the_registration_matrix(koide3_result):
    completed = run_example("align.py")
    assert completed.returncode == 0, completed.stderr
    lines = completed.stdout.splitlines()
    assert lines[0] == f"CONVERGENCE: {koide3_result.message}"
    printed = np.array([[float(v) for v in line.split()] for line in lines[1:]])
    np.testing.assert_allclose(printed, koide3_result.reference_from_input, atol=1e-8)
    assert completed.stderr.startswith("ML-NDT registration: CONVERGENCE")


def test_align_with_a_guess_and_options(koide3):
    completed = run_example(
        "align.py",
        str(BUNDLED_DATA_DIR / "koide3" / "251370668.pcd"),
        str(BUNDLED_DATA_DIR / "koide3" / "251371071.pcd"),
        "--initial-guess=0.4,0.1,0,0,0,-1",
        "--initial-uncertainty=0.2,2",
        "--backend=lm",
    )
    assert completed.returncode == 0, completed.stderr
    expected = mlndt.register(
        *koide3,
        initial=mlndt.pose_from_xi([0.4, 0.1, 0, 0, 0, -1], degrees=True),
        initial_uncertainty=(0.2, 2),
        backend={"type": "lm"},
    )
    printed = np.loadtxt(completed.stdout.splitlines()[1:])
    np.testing.assert_allclose(printed, expected.reference_from_input, atol=1e-8)


def test_align_exits_1_on_a_bad_file(tmp_path):
    completed = run_example("align.py", str(tmp_path / "missing.pcd"), str(tmp_path / "missing.pcd"))
    assert completed.returncode == 1
    assert completed.stderr.startswith("align.py: ") and "missing.pcd: cannot open file" in completed.stderr


def test_sequence_writes_the_kitti_trajectory(tmp_path):
    output = tmp_path / "trajectory.txt"
    completed = run_example("sequence.py", "--output", str(output))
    assert completed.returncode == 0, completed.stderr
    assert completed.stdout.count("CONVERGENCE") == 7
    poses = np.loadtxt(output)
    assert poses.shape == (8, 12)
    np.testing.assert_array_equal(poses[0], np.eye(4)[:3].ravel())
    # Against the chained consensus of the consecutive bundled pairs.
    chained = np.eye(4)
    for i in range(7):
        step, _ = reference_transform(BUNDLED_DATA_DIR / "kitti" / "reference_pairs.json", f"{i}_{i + 1}")
        chained = chained @ step
    last = np.eye(4)
    last[:3] = poses[-1].reshape(3, 4)
    assert translation_error_m(chained, last) < 0.3
    np.testing.assert_allclose(last[:3, :3].T @ last[:3, :3], np.eye(3), atol=1e-8)
