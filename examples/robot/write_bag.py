#!/usr/bin/env python3
"""A ROS 2 bag of the robot driving through scenes/robot_world.json (docs/ros2.md): at every pose of
examples/robot/path.csv the 3-D lidar's scan (PointCloud2), a ring of 8 sonars (Range), the front
camera's frame (Image and CameraInfo, rendered by revolve-render) and the robot's pose (/tf), with
the sensors' mountings on /tf_static. The poses carry no time: they are stamped --period apart.

  PYTHONPATH=build/python /usr/bin/python3 examples/robot/write_bag.py -o out/robot_bag
  ros2 bag info out/robot_bag        # or open out/robot_bag/robot_bag.mcap in Foxglove

Needs Debian 13's python3-rosbags (revolve.ros2 says so and this exits 1 without it) and Pillow
(python3-pil) to read the camera's PNGs. An earlier bag at the output path is replaced.
"""

import argparse
import os
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[2]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--scene", default=ROOT / "scenes" / "robot_world.json")
    parser.add_argument("--poses", default=ROOT / "examples" / "robot" / "path.csv")
    parser.add_argument("--lidar", default=ROOT / "examples" / "robot" / "lidar_3d.json")
    parser.add_argument("--sonars", default=ROOT / "examples" / "robot" / "sonar_ring.json")
    parser.add_argument("--camera", default=ROOT / "examples" / "robot" / "camera_front.json")
    parser.add_argument("--period", type=float, default=None,
                        help="seconds between poses without times (default revolve.ros2.DEFAULT_PERIOD, 0.1)")
    parser.add_argument("--spp", type=int, default=16, help="the camera's samples a pixel (revolve-render --spp)")
    parser.add_argument("--render", default=pathlib.Path(os.environ.get("REVOLVE_BIN_DIR", ROOT / "build" / "bin")) / "revolve-render",
                        help="the revolve-render executable (default build/bin/revolve-render)")
    parser.add_argument("-o", "--output", default=ROOT / "out" / "robot_bag", help="the bag's folder (default out/robot_bag)")
    args = parser.parse_args()

    try:
        from revolve import ros2
    except ImportError as error:
        print(f"{sys.argv[0]}: {error}", file=sys.stderr)
        return 1
    import revolve

    poses = revolve.read_poses(args.poses)
    stamps = ros2.pose_stamps(poses, period=args.period)
    scene = revolve.Scene(args.scene)
    scan = revolve.Lidar(args.lidar).scan(scene, poses)
    sonars = revolve.RangeSensors(args.sonars)
    readings = sonars.read(scene, poses)

    output = pathlib.Path(args.output)
    output.parent.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="frames-", dir=output.parent) as frames:
        # The camera's frames: front_0000.png and front_0000.json (CameraInfo's fields, the pose's time), ...
        render = [str(args.render), str(args.scene), "--camera", str(args.camera), "--poses", str(args.poses),
                  "-o", os.path.join(frames, "front.png"), "--spp", str(args.spp)]
        if not os.access(render[0], os.X_OK):
            print(f"{sys.argv[0]}: --render {render[0]}: no such executable (build it: bash scripts/build.sh)", file=sys.stderr)
            return 1
        done = subprocess.run(render, stdout=subprocess.DEVNULL)
        if done.returncode != 0:
            print(f"{sys.argv[0]}: revolve-render exited {done.returncode} (its message is above)", file=sys.stderr)
            return 1
        with ros2.BagWriter(output, overwrite=True) as bag:
            bag.write_static_transforms(stamps[0], [
                ("base_link", "lidar", ros2.sensor_mounting(args.lidar)),
                *[("base_link", name, mounting) for name, mounting in zip(sonars.names, sonars.mounting)],
                ("base_link", "camera", ros2.sensor_mounting(args.camera)),
                ("camera", "camera_optical", ros2.OPTICAL_FROM_CAMERA),
            ])
            for i, stamp in enumerate(stamps):
                bag.write_robot_pose(stamp, poses[i])
                bag.write_point_cloud(stamp, scan, i)
                bag.write_ranges(stamp, readings["range"][i], sonars.names, sonars.field_of_view, sonars.min_range,
                                 sonars.max_range, sonars.radiation_type, variance=sonars.noise_stddev ** 2)
                image, info = ros2.read_camera_frame(os.path.join(frames, f"front_{i:04d}.json"))
                bag.write_image(stamp, image)
                bag.write_camera_info(stamp, info)
    print(f"{output}: {len(stamps)} poses from {stamps[0]:g} s to {stamps[-1]:g} s")
    for topic, count in bag.counts.items():
        print(f"  {topic}: {count}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
