"""KITTI 00 frames 0-7 of the shared data set against its reference_pairs.json
(the consensus of five third-party registrations; KITTI's own ground truth
is off for these frames, see the data set's README). Skips without
MLNDT_DATA_DIR."""

import pytest

import mlndt
from conftest import reference_transform, rotation_error_deg, translation_error_m

KITTI = "kitti00_frames_0000_0007"


def register_pair(folder, key):
    i, j = (int(n) for n in key.split("_"))
    reference = mlndt.read_cloud(folder / "pcd" / f"{i:06d}.pcd")
    input = mlndt.read_cloud(folder / "pcd" / f"{j:06d}.pcd")
    expected, entry = reference_transform(folder / "reference_pairs.json", key)
    return mlndt.register(reference, input), expected, entry


def test_pair_0_1_within_2cm_and_0_1_deg(shared_data_dir):
    result, expected, entry = register_pair(shared_data_dir / KITTI, "0_1")
    assert result.termination_type == "CONVERGENCE", result.message
    assert translation_error_m(expected, result.reference_from_input) < 0.02
    assert rotation_error_deg(expected, result.reference_from_input) < 0.1


@pytest.mark.parametrize("key", ["1_2", "2_3", "3_4", "4_5", "5_6", "6_7", "0_2", "0_3", "0_5"])
def test_other_pairs_within_10cm_and_0_2_deg(shared_data_dir, key):
    result, expected, _ = register_pair(shared_data_dir / KITTI, key)
    assert result.usable, result.message
    assert translation_error_m(expected, result.reference_from_input) < 0.1
    assert rotation_error_deg(expected, result.reference_from_input) < 0.2
