# Type stubs of the mlndt Python module (python/src/*.cc). The option
# TypedDicts list the fields of the C++ option structs (python/src/options.cc
# binds them); python/tests/test_stubs.py checks that they match
# mlndt.default_options() and that every public name has a stub.

import os
from typing import Any, Literal, Sequence, TypedDict, Union

import numpy as np
import numpy.typing as npt

__version__: str

PointsLike = npt.ArrayLike  # (N, 3) array of x, y, z [m], float64 or float32.
TransformLike = npt.ArrayLike  # 4x4 (or 3x4) rigid transform.
PathLike = Union[str, os.PathLike[str]]
Preset = Literal["default", "paper"]

class RangeFilterOptions(TypedDict, total=False):
    min_range_m: float
    max_range_m: float
    saturated_range_fraction: float

class CellRegularization(TypedDict, total=False):
    min_eigenvalue_ratio: float
    min_eigenvalue_m2: float

class LayeredGridOptions(TypedDict, total=False):
    division_constant: int
    num_layers: int
    finest_cell_size_m: float
    min_covered_fraction: float
    cell_size_m: float
    max_num_layers: int
    min_points_per_cell: int
    regularization: CellRegularization
    coarse_weighting: str  # POINTS | FINEST_CELLS

class SamplingOptions(TypedDict, total=False):
    method: str  # ALL | RANDOM | GBS | VOXEL_CENTROID
    random_fraction: float
    random_count: int
    gbs_cell_size_m: float
    gbs_points_per_cell: int
    gbs_min_points_per_cell: int
    voxel_size_m: float
    seed: int

class LayerScheduleOptions(TypedDict, total=False):
    start_layer: int
    iterations_per_layer: int
    max_final_iterations: int
    step_tolerance: float
    coarse_step_tolerance: float
    end_coarse_layer_on_rejected_step: bool
    max_coarse_point_stride: int
    cells_per_uncertainty: float

class ObjectiveOptions(TypedDict, total=False):
    unmatched_policy: str  # ZERO_RESIDUAL | NEAREST_CELL
    loss: str  # NONE | HUBER | CAUCHY
    loss_scale: float

class CeresBackendOptions(TypedDict, total=False):
    linear_solver_type: str  # ceres::LinearSolverType names
    trust_region_strategy_type: str  # LEVENBERG_MARQUARDT | DOGLEG

class NewtonOptions(TypedDict, total=False):
    line_search: bool
    max_line_search_steps: int
    min_eigenvalue_ratio: float

class LevenbergMarquardtOptions(TypedDict, total=False):
    initial_lambda_factor: float
    lambda_decrease: float
    lambda_increase: float
    residual: str  # WHITENED | SCALAR_SCORE

class BackendOptions(TypedDict, total=False):
    type: str  # CERES | NEWTON | LEVENBERG_MARQUARDT (or "lm")
    ceres: CeresBackendOptions
    newton: NewtonOptions
    levenberg_marquardt: LevenbergMarquardtOptions

class QualityCheckOptions(TypedDict, total=False):
    enabled: bool
    inlier_gate: float
    max_median_distance: float
    min_inlier_fraction: float
    max_mean_score: float
    min_constraint_ratio: float
    max_flatness: float
    min_probe_evidence: float
    min_fit_points: int

class InitialGuessUncertainty(TypedDict, total=False):
    given: bool
    translation_m: float
    rotation_deg: float

class RetryOptions(TypedDict, total=False):
    yaw_seeds_deg: Sequence[float]
    weak_direction_rounds: int
    weak_direction_min_flatness: float
    scan_pattern_reach_cells: float

class RegistrationOptions(TypedDict, total=False):
    range_filter: RangeFilterOptions
    grid: LayeredGridOptions
    sampling: SamplingOptions
    schedule: LayerScheduleOptions
    objective: ObjectiveOptions
    backend: BackendOptions
    num_threads: int
    min_matched_fraction: float
    quality_check: QualityCheckOptions
    initial_uncertainty: InitialGuessUncertainty
    retry: RetryOptions

InitialUncertaintyLike = Union[tuple[float, float], Sequence[float], InitialGuessUncertainty, None]

class FitQuality(TypedDict):
    points: int
    own_cell_fraction: float
    inlier_fraction: float
    mean_score: float
    median_distance: float
    constraint_ratio: float
    flatness: float
    probe_evidence: float

class IterationRecord(TypedDict):
    iteration: int
    layer: int
    score: float
    step_norm: float
    step_is_successful: bool
    reference_from_input_xi: npt.NDArray[np.float64]  # (6,), m and rad
    time_s: float

class LayerInfo(TypedDict):
    layer: int
    cell_size_m: float
    dims: tuple[int, int, int]
    occupied_cells: int
    sparse_cells: int
    degenerate_cells: int

class LayerCells(TypedDict):
    means: npt.NDArray[np.float64]  # (k, 3)
    covariances: npt.NDArray[np.float64]  # (k, 3, 3)
    counts: npt.NDArray[np.int64]  # (k,)

class RegistrationResult:
    """What a registration reports (mlndt::RegistrationSummary)."""

    @property
    def reference_from_input(self) -> npt.NDArray[np.float64]:
        """4x4 transform mapping input points into the reference frame."""
    @property
    def reference_from_input_xi(self) -> npt.NDArray[np.float64]:
        """(tx, ty, tz, alpha, beta, gamma), Eq. 11, metres and radians."""
    @property
    def initial_reference_from_input_xi(self) -> npt.NDArray[np.float64]: ...
    @property
    def termination(self) -> str:
        """CONVERGENCE | NO_CONVERGENCE | FAILURE | LOW_QUALITY | DEGENERATE."""
    @property
    def converged(self) -> bool:
        """termination == "CONVERGENCE"."""
    @property
    def usable(self) -> bool:
        """CONVERGENCE or NO_CONVERGENCE: the pose passed the quality check."""
    @property
    def message(self) -> str: ...
    @property
    def algorithm(self) -> str: ...
    @property
    def quality(self) -> FitQuality: ...
    @property
    def degenerate_directions(self) -> npt.NDArray[np.float64]:
        """(k, 6) directions of the pose vector the fit does not constrain."""
    @property
    def covariance(self) -> npt.NDArray[np.float64]:
        """6x6, m and rad, of (tx, ty, tz, alpha, beta, gamma); inf along degenerate directions."""
    @property
    def hessian(self) -> npt.NDArray[np.float64]: ...
    @property
    def score(self) -> float: ...
    @property
    def initial_score(self) -> float: ...
    @property
    def iterations(self) -> int: ...
    @property
    def iterations_per_layer(self) -> list[int]: ...
    @property
    def attempts(self) -> int: ...
    @property
    def start_layer(self) -> int: ...
    @property
    def num_layers(self) -> int: ...
    @property
    def finest_cell_size_m(self) -> float: ...
    @property
    def trace(self) -> list[IterationRecord]: ...
    @property
    def input_points(self) -> int: ...
    @property
    def range_filtered_points(self) -> int: ...
    @property
    def sampled_points(self) -> int: ...
    @property
    def matched_points(self) -> int: ...
    @property
    def unmatched_points(self) -> int: ...
    @property
    def map_occupied_cells(self) -> int: ...
    @property
    def map_bytes(self) -> int: ...
    @property
    def total_time_s(self) -> float: ...
    @property
    def map_time_s(self) -> float: ...
    @property
    def sampling_time_s(self) -> float: ...
    @property
    def solve_time_s(self) -> float: ...
    def report(self) -> str:
        """The library's FullReport (what mlndt_align prints)."""
    def brief_report(self) -> str: ...

def register(
    reference: PointsLike,
    input: PointsLike,
    initial: TransformLike | None = None,
    initial_uncertainty: InitialUncertaintyLike = None,
    *,
    preset: Preset = "default",
    range_filter: RangeFilterOptions = ...,
    grid: LayeredGridOptions = ...,
    sampling: SamplingOptions = ...,
    schedule: LayerScheduleOptions = ...,
    objective: ObjectiveOptions = ...,
    backend: BackendOptions = ...,
    num_threads: int = ...,
    min_matched_fraction: float = ...,
    quality_check: QualityCheckOptions = ...,
    retry: RetryOptions = ...,
) -> RegistrationResult:
    """Registers input onto reference with ML-NDT; help(mlndt.register) lists the options."""

class LayeredMap:
    """A layered NDT map (mlndt::LayeredGrid): build once, save, load, register against."""

    @staticmethod
    def build(
        points: PointsLike,
        num_threads: int = 1,
        *,
        preset: Preset = "default",
        division_constant: int = ...,
        num_layers: int = ...,
        finest_cell_size_m: float = ...,
        min_covered_fraction: float = ...,
        cell_size_m: float = ...,
        max_num_layers: int = ...,
        min_points_per_cell: int = ...,
        regularization: CellRegularization = ...,
        coarse_weighting: str = ...,
    ) -> LayeredMap: ...
    @staticmethod
    def load(path: PathLike) -> LayeredMap: ...
    def save(self, path: PathLike) -> None: ...
    def register(
        self,
        input: PointsLike,
        initial: TransformLike | None = None,
        initial_uncertainty: InitialUncertaintyLike = None,
        *,
        preset: Preset = "default",
        range_filter: RangeFilterOptions = ...,
        sampling: SamplingOptions = ...,
        schedule: LayerScheduleOptions = ...,
        objective: ObjectiveOptions = ...,
        backend: BackendOptions = ...,
        num_threads: int = ...,
        min_matched_fraction: float = ...,
        quality_check: QualityCheckOptions = ...,
        retry: RetryOptions = ...,
    ) -> RegistrationResult: ...
    @property
    def layers(self) -> list[LayerInfo]: ...
    @property
    def num_layers(self) -> int: ...
    @property
    def bytes(self) -> int: ...
    @property
    def bounds(self) -> npt.NDArray[np.float64]:
        """2x3: min row, max row [m]."""
    @property
    def num_points(self) -> int: ...
    @property
    def options(self) -> LayeredGridOptions: ...
    def cells(self, layer: int) -> LayerCells: ...

def default_options(preset: Preset = "default") -> dict[str, Any]: ...
def resolve_options(
    initial_uncertainty: InitialUncertaintyLike = None, *, preset: Preset = "default", **options: Any
) -> dict[str, Any]: ...
def read_cloud(path: PathLike) -> npt.NDArray[np.float64]: ...
def write_cloud(path: PathLike, points: PointsLike) -> None: ...
def filter_range(
    points: PointsLike,
    *,
    min_range_m: float = ...,
    max_range_m: float = ...,
    saturated_range_fraction: float = ...,
) -> npt.NDArray[np.float64]: ...
def pose_from_xi(xi: Sequence[float] | npt.ArrayLike, degrees: bool = False) -> npt.NDArray[np.float64]: ...
def xi_from_pose(pose: TransformLike) -> npt.NDArray[np.float64]: ...

class LocalizationResult:
    """One scan's localisation (mlndt::LocalizationResult); poses are map_from_scan."""

    @property
    def index(self) -> int: ...
    @property
    def predicted_map_from_scan(self) -> np.ndarray: ...
    @property
    def map_from_scan(self) -> np.ndarray: ...
    @property
    def termination(self) -> str: ...
    @property
    def usable(self) -> bool: ...
    @property
    def message(self) -> str: ...
    @property
    def quality(self) -> dict[str, float]: ...
    @property
    def iterations(self) -> int: ...
    @property
    def input_points(self) -> int: ...
    @property
    def sampled_points(self) -> int: ...
    @property
    def matched_points(self) -> int: ...
    @property
    def score(self) -> float: ...
    @property
    def sampling_time_s(self) -> float: ...
    @property
    def solve_time_s(self) -> float: ...
    @property
    def registration_time_s(self) -> float: ...

class Localizer:
    """Localisation of a scan sequence against one prebuilt map (mlndt::Localizer)."""

    def __init__(
        self,
        map: LayeredMap,
        first_map_from_scan: TransformLike | None = None,
        motion_model: Literal["constant_velocity", "constant_pose"] = "constant_velocity",
        initial_uncertainty: InitialUncertaintyLike = None,
        *,
        preset: Preset = "default",
        range_filter: RangeFilterOptions = ...,
        sampling: SamplingOptions = ...,
        schedule: LayerScheduleOptions = ...,
        objective: ObjectiveOptions = ...,
        backend: BackendOptions = ...,
        num_threads: int = ...,
        min_matched_fraction: float = ...,
        quality_check: QualityCheckOptions = ...,
        retry: RetryOptions = ...,
    ) -> None: ...
    def localize(self, scan: PointsLike) -> LocalizationResult: ...
    def predict_next(self) -> np.ndarray: ...
    @property
    def num_localized(self) -> int: ...

class LocalMapOptions(TypedDict, total=False):
    max_keyframes: int
    radius_m: float

class KeyframeOptions(TypedDict, total=False):
    min_translation_m: float
    min_rotation_deg: float

class MotionPredictionOptions(TypedDict, total=False):
    window: int
    factor: float
    min_translation_m: float
    max_translation_m: float
    min_rotation_deg: float
    max_rotation_deg: float

class ConfirmationOptions(TypedDict, total=False):
    enabled: bool
    min_correction_fraction: float
    check_last_scan: bool

class RecoveryOptions(TypedDict, total=False):
    max_search_starts: int
    yaw_step_deg: float

class OdometryResult:
    """One scan of the odometry (mlndt::OdometryResult); poses are world_from_sensor."""

    @property
    def index(self) -> int: ...
    @property
    def stamp_s(self) -> float: ...
    @property
    def predicted(self) -> np.ndarray: ...
    @property
    def world_from_sensor(self) -> np.ndarray: ...
    @property
    def uncertainty(self) -> tuple[float, float]: ...
    @property
    def termination(self) -> str: ...
    @property
    def message(self) -> str: ...
    @property
    def fallback(self) -> bool: ...
    @property
    def keyframe(self) -> bool: ...
    @property
    def search_starts(self) -> int: ...
    @property
    def recovered(self) -> bool: ...
    @property
    def interpolated(self) -> bool: ...
    @property
    def bridged(self) -> list[tuple[int, np.ndarray]]: ...
    @property
    def deskewed(self) -> bool: ...
    @property
    def start_layer(self) -> int: ...
    @property
    def num_layers(self) -> int: ...
    @property
    def iterations(self) -> int: ...
    @property
    def sampled_points(self) -> int: ...
    @property
    def quality(self) -> dict[str, float]: ...
    @property
    def correction_m(self) -> float: ...
    @property
    def correction_deg(self) -> float: ...
    @property
    def map_keyframes(self) -> int: ...
    @property
    def map_points(self) -> int: ...
    @property
    def registration_time_s(self) -> float: ...
    @property
    def map_time_s(self) -> float: ...
    @property
    def total_time_s(self) -> float: ...

class Odometry:
    """Scan-to-local-map LiDAR odometry with ML-NDT (mlndt::Odometry), scan by scan."""

    def __init__(
        self,
        *,
        local_map: LocalMapOptions = ...,
        keyframes: KeyframeOptions = ...,
        prediction: MotionPredictionOptions = ...,
        deskew: bool = ...,
        gate_factor: float = ...,
        recovery: RecoveryOptions = ...,
        max_flatness: float = ...,
        weak_direction_rounds: int = ...,
        max_mean_score: float = ...,
        confirmation: ConfirmationOptions = ...,
        preset: Preset = "default",
        range_filter: RangeFilterOptions = ...,
        grid: LayeredGridOptions = ...,
        sampling: SamplingOptions = ...,
        schedule: LayerScheduleOptions = ...,
        objective: ObjectiveOptions = ...,
        backend: BackendOptions = ...,
        num_threads: int = ...,
        min_matched_fraction: float = ...,
        quality_check: QualityCheckOptions = ...,
        retry: RetryOptions = ...,
    ) -> None: ...
    def process(
        self, points: PointsLike, stamp_s: float, point_times: npt.ArrayLike | None = None
    ) -> OdometryResult: ...
    @property
    def num_processed(self) -> int: ...

def run_odometry(
    scans: Sequence[PathLike | PointsLike],
    stamps: Sequence[float] | npt.ArrayLike | None = None,
    point_times: Sequence[npt.ArrayLike | None] | None = None,
    *,
    local_map: LocalMapOptions = ...,
    keyframes: KeyframeOptions = ...,
    prediction: MotionPredictionOptions = ...,
    deskew: bool = ...,
    gate_factor: float = ...,
    recovery: RecoveryOptions = ...,
    max_flatness: float = ...,
    weak_direction_rounds: int = ...,
    max_mean_score: float = ...,
    confirmation: ConfirmationOptions = ...,
    preset: Preset = "default",
    range_filter: RangeFilterOptions = ...,
    grid: LayeredGridOptions = ...,
    sampling: SamplingOptions = ...,
    schedule: LayerScheduleOptions = ...,
    objective: ObjectiveOptions = ...,
    backend: BackendOptions = ...,
    num_threads: int = ...,
    min_matched_fraction: float = ...,
    quality_check: QualityCheckOptions = ...,
    retry: RetryOptions = ...,
) -> list[OdometryResult]: ...
