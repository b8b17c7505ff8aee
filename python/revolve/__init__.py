"""revolve: surfaces of revolution ray traced exactly inside Embree, from Python.

A surface of revolution is a profile of points (r, z) swept a full turn about the z axis. revolve
traces it exactly (the MIBIT search of Baciu, Jia & Lam 2001 over the profile, Wang's ray/cone
intersection at its leaves, splines solved as curves) instead of tessellating it.

RaycastingScene     Open3D's RaycastingScene (0.19) with exact surfaces of revolution beside meshes
Scene, Lidar        a scene file and revolve-lidar's range-finder, bit for bit the tool's scans
RangeSensors        sonar and infrared cones (ROS Range): the nearest surface inside each, exact
                    (these four pickle, copy and deepcopy: the pickle holds what builds them)
ScanFile            a scan written as revolve-lidar writes it (PCD or CSV), shard by shard
scan_shard          one shard of a scan, from a Scene and Lidar sent along (or files loaded once a process)
shard_poses         the poses one shard of a scan needs (a moving sensor's path past its sweeps)
cylinder_clearance  revolve-clearance's robot clearance
read_poses          a POSES.csv file as the tools read it
tessellate          a profile swept into a triangle mesh (for triangle ray casters)
"""

from . import _pickle
from ._mesh import tessellate
from ._pinhole import create_rays_pinhole as _create_rays_pinhole
from ._shards import scan_shard, shard_poses
from ._revolve import (
    Lidar,
    ProfileError,
    RangeSensors,
    RaycastingScene,
    ScanFile,
    Scene,
    cylinder_clearance,
    embree_version,
    read_poses,
)

RaycastingScene.create_rays_pinhole = staticmethod(_create_rays_pinhole)
_pickle.install()

__all__ = [
    "Lidar",
    "ProfileError",
    "RangeSensors",
    "RaycastingScene",
    "ScanFile",
    "Scene",
    "cylinder_clearance",
    "embree_version",
    "read_poses",
    "scan_shard",
    "shard_poses",
    "tessellate",
]
