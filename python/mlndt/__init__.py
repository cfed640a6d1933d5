"""ML-NDT scan matching (Ulas & Temeltas 2013) on numpy arrays.

The Python face of the mlndt C++ library: register two scans, build, save and
load layered NDT maps and register against them, read and write cloud files.

    import mlndt
    reference = mlndt.read_cloud("data/koide3/251370668.pcd")
    input = mlndt.read_cloud("data/koide3/251371071.pcd")
    result = mlndt.register(reference, input)
    print(result.termination, result.reference_from_input)

help(mlndt.register) lists every option with its default.
"""

from ._mlndt import (
    LayeredMap,
    RegistrationResult,
    __version__,
    default_options,
    filter_range,
    pose_from_xi,
    read_cloud,
    register,
    write_cloud,
    xi_from_pose,
)

__all__ = [
    "LayeredMap",
    "RegistrationResult",
    "__version__",
    "default_options",
    "filter_range",
    "pose_from_xi",
    "read_cloud",
    "register",
    "write_cloud",
    "xi_from_pose",
]

# The classes are defined in mlndt._mlndt; they are used as mlndt.X.
LayeredMap.__module__ = "mlndt"
RegistrationResult.__module__ = "mlndt"
