"""ML-NDT scan matching (Ulas & Temeltas 2013) on numpy arrays.

The Python face of the mlndt C++ library: register two scans, build, save and
load layered NDT maps and register against them, localise a scan sequence
against a map (Localizer), run scan-to-local-map odometry (Odometry,
run_odometry), read and write cloud files. Submodule (imported
by name): mlndt.distributed (pairs and scans fanned out to Dask workers).
The development build (scripts/test.sh) also makes the separate module
mlndt_lab (trajectory evaluation, sequence runs and ROS 1 bag reading, as
mlndt_eval, mlndt_sequence and the tools' --bag do them); pip install does not.

    import mlndt
    reference = mlndt.read_cloud("data/koide3/251370668.pcd")
    input = mlndt.read_cloud("data/koide3/251371071.pcd")
    result = mlndt.register(reference, input)
    print(result.termination_type, result.reference_from_input)

help(mlndt.register) lists every option with its default.
"""

from ._mlndt import (
    LayeredMap,
    LocalizationResult,
    Localizer,
    Odometry,
    OdometryResult,
    RegistrationResult,
    __version__,
    default_options,
    filter_range,
    pose_from_xi,
    read_cloud,
    register,
    resolve_options,
    run_odometry,
    write_cloud,
    xi_from_pose,
)

__all__ = [
    "LayeredMap",
    "LocalizationResult",
    "Localizer",
    "Odometry",
    "OdometryResult",
    "RegistrationResult",
    "__version__",
    "default_options",
    "filter_range",
    "pose_from_xi",
    "read_cloud",
    "register",
    "resolve_options",
    "run_odometry",
    "write_cloud",
    "xi_from_pose",
]

# The classes are defined in mlndt._mlndt; they are used as mlndt.X.
LayeredMap.__module__ = "mlndt"
LocalizationResult.__module__ = "mlndt"
Localizer.__module__ = "mlndt"
Odometry.__module__ = "mlndt"
OdometryResult.__module__ = "mlndt"
RegistrationResult.__module__ = "mlndt"
