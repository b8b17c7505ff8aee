"""Pickling, copy and deepcopy of RaycastingScene, Scene, Lidar and RangeSensors.

A pickle holds what builds the object, never Embree's or the search structures' memory, and the
object is built again from it on loading: a RaycastingScene as its additions in id order (each
revolution's points, spline kind, tolerance and 4x4 placement as given; each mesh's vertex and
index arrays, which protocol 5 carries out of band as numpy's buffers), so that every id and every
answer is the original's; a Scene as its scene file's text and every profile CSV's text it read, with
its build options, so that a process with no access to the files rebuilds it; a Lidar or
RangeSensors as its sensor JSON text (and a beam pattern's text). Each pickle carries FORMAT_VERSION;
another version is refused with a ValueError naming both.
"""

import warnings

from ._revolve import Lidar, RangeSensors, RaycastingScene, Scene

FORMAT_VERSION = 1


def _check_version(version, kind):
    if version != FORMAT_VERSION:
        raise ValueError(f"revolve.{kind} pickle: format version {version!r} is not supported; this revolve reads "
                         f"version {FORMAT_VERSION} (the pickle was made by another revolve)")


def _restore_raycasting_scene(version, additions):
    _check_version(version, "RaycastingScene")
    scene = RaycastingScene()
    # The profiles' warnings were given when they were first added.
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for addition in additions:
            if addition[0] == "revolution":
                _, points, transform, spline, tolerance = addition
                scene.add_revolution(points, transform=transform, spline=spline, tolerance=tolerance)
            elif addition[0] == "triangles":
                _, vertices, triangles = addition
                scene.add_triangles(vertices, triangles)
            else:
                raise ValueError(f"revolve.RaycastingScene pickle: unknown addition {addition[0]!r}")
    return scene


def _reduce_raycasting_scene(self, protocol=None):
    return _restore_raycasting_scene, (FORMAT_VERSION, self._additions())


def _restore_scene(version, path, text, csvs, geometry, slices):
    _check_version(version, "Scene")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return Scene._from_sources(path, text, csvs, geometry, slices)


def _reduce_scene(self, protocol=None):
    return _restore_scene, (FORMAT_VERSION, *self._sources())


def _restore_lidar(version, file, text, patterns):
    _check_version(version, "Lidar")
    return Lidar._from_sources(file, text, patterns)


def _reduce_lidar(self, protocol=None):
    return _restore_lidar, (FORMAT_VERSION, *self._sources())


def _restore_range_sensors(version, file, text):
    _check_version(version, "RangeSensors")
    return RangeSensors._from_sources(file, text)


def _reduce_range_sensors(self, protocol=None):
    return _restore_range_sensors, (FORMAT_VERSION, *self._sources())


def install():
    """Gives the classes their __reduce_ex__ (pickle, copy.copy and copy.deepcopy use it)."""
    RaycastingScene.__reduce_ex__ = _reduce_raycasting_scene
    Scene.__reduce_ex__ = _reduce_scene
    Lidar.__reduce_ex__ = _reduce_lidar
    RangeSensors.__reduce_ex__ = _reduce_range_sensors
