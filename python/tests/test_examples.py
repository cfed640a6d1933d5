"""examples/python/: align.py prints the registration's 4x4, sequence.py
writes a KITTI trajectory of the bundled KITTI frames, posegraph_livox.py's
graph (calibrated weight) undoes most of the perturbed odometry's drift on
the shared Livox sequence."""

import os
import subprocess

import numpy as np

import mlndt
from conftest import (
    BUNDLED_DATA_DIR,
    PYTHON,
    SOURCE_DIR,
    TOOLS_DIR,
    read_kitti_lines,
    reference_transform,
    translation_error_m,
)

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


def test_posegraph_livox_undoes_the_perturbed_odometry(tmp_path, shared_data_dir):
    data = shared_data_dir / "fastlio_avia_hku_2_sequence"
    completed = run_example(
        "posegraph_livox.py",
        "--data",
        str(data),
        "--output",
        str(tmp_path),
        "--scales",
        "0.055",
        "--tool",
        str(TOOLS_DIR / "mlndt_posegraph"),
    )
    assert completed.returncode == 0, completed.stderr
    row = completed.stdout.splitlines()[-1].split("|")
    assert row[1].strip() == "0.055"
    noisy_ate, graph_ate = float(row[2]), float(row[3])
    # The perturbation drifts by decimetres; the graph brings the trajectory
    # back to within a fifth of that (README: 0.761 -> 0.081 m, seed 1).
    assert noisy_ate > 0.3 and graph_ate < noisy_ate / 5, completed.stdout
    # The odometry it wrote: every step perturbed, none by more than 6 sigma.
    reference = read_kitti_lines(data / "odom_poses.txt")
    noisy = read_kitti_lines(tmp_path / "noisy_odometry.txt")
    assert len(noisy) == len(reference) == 250
    for k in range(1, 250):
        step = np.linalg.inv(reference[k - 1]) @ reference[k]
        noisy_step = np.linalg.inv(noisy[k - 1]) @ noisy[k]
        offset = np.linalg.norm((np.linalg.inv(step) @ noisy_step)[:3, 3])
        assert 0.0 < offset < 6 * 0.02 * np.sqrt(3), k
