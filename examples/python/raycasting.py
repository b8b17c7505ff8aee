#!/usr/bin/python3
"""The example of docs/python.md: revolve's RaycastingScene where Open3D's would be, with exact surfaces of
revolution beside a triangle mesh. Run it as PYTHONPATH=build/python /usr/bin/python3 examples/python/raycasting.py."""

import numpy as np

import revolve  # in place of: import open3d as o3d; o3d.t.geometry.RaycastingScene

scene = revolve.RaycastingScene()
# Profiles are (r, z) points swept about the z axis. A can of radius 0.5 and height 1, moved to x = -1:
move = np.eye(4)
move[0, 3] = -1.0
can = scene.add_revolution([[0, 0], [0.5, 0], [0.5, 1], [0, 1]], transform=move)
# A vase through six points, traced as the Catmull-Rom curve itself, at x = +1.
move[0, 3] = 1.0
vase = scene.add_revolution([[0, 0], [0.3, 0], [0.4, 0.3], [0.25, 0.7], [0.3, 0.9], [0, 0.9]], transform=move, spline="catmull-rom")

# Distances are exact; inside a closed profile, negative (decided from the profile, not by rays).
points = np.array([[-1, 0, 2], [-1, 0, 0.5]], np.float32)
print(f"above the can: {scene.compute_distance(points[:1])[0]:.6f}; its centre: {scene.compute_signed_distance(points[1:])[0]:+.6f}")

# Meshes beside them, as in Open3D: a floor of two triangles at z = 0.
floor = scene.add_triangles(np.array([[-3, -3, 0], [3, -3, 0], [3, 3, 0], [-3, 3, 0]], np.float32),
                            np.array([[0, 1, 2], [0, 2, 3]], np.uint32))
# A camera's rays, Open3D's layout: (height, width, 6) float32.
rays = scene.create_rays_pinhole(fov_deg=60, center=[0, 0, 0.5], eye=[0, -4, 2], up=[0, 0, 1], width_px=640, height_px=480)
hits = scene.cast_rays(rays)  # t_hit, geometry_ids, primitive_ids, primitive_uvs, primitive_normals
seen = np.bincount(hits["geometry_ids"][hits["geometry_ids"] != scene.INVALID_ID], minlength=3)
print(f"depth image {hits['t_hit'].shape}: {seen[can]} pixels see the can, {seen[vase]} the vase, {seen[floor]} the floor")
# Straight down onto the can's lid from z = 3: 2 away, facing up.
down = scene.cast_rays(np.array([[-1.2, 0.1, 3, 0, 0, -1]], np.float32))
print(f"the can's lid: t = {down['t_hit'][0]:.6f}, normal {down['primitive_normals'][0].round(6).tolist()}")
