"""The `lists` command: rgb.txt and depth.txt for a folder of PNGs, so that dynvo-cli can read
a user's own recording (tools/make_lists.sh).

Stamps come from the file names when every name is a number of seconds (TUM's and most
recorders' `1341846313.553992.png`); otherwise the k-th colour and the k-th depth image (in
the order of the numbers in their names) are one frame, stamped k / fps."""
from __future__ import annotations

import argparse
import os
import re
from typing import Optional

from .common import ToolError

NUMBER = re.compile(r"^[0-9]+(\.[0-9]+)?$")
DIGITS = re.compile(r"([0-9]+)")


def add_parser(commands: argparse._SubParsersAction) -> None:
    """The `lists` command."""
    parser = commands.add_parser("lists", help="rgb.txt and depth.txt for a folder of PNGs",
                                 description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("folder", metavar="SEQ_DIR", help="the sequence folder, holding the two image folders")
    parser.add_argument("--rgb", default="rgb", metavar="SUBDIR", help="colour images, inside SEQ_DIR (default rgb)")
    parser.add_argument("--depth", default="depth", metavar="SUBDIR",
                        help="16-bit depth images, inside SEQ_DIR (default depth)")
    parser.add_argument("--fps", type=float, default=30.0,
                        help="frame rate, when the names are not stamps (default 30)")
    parser.add_argument("--force", action="store_true", help="replace existing rgb.txt and depth.txt")
    parser.set_defaults(run=run)


def natural_key(name: str) -> list:
    """Orders frame_2.png before frame_10.png."""
    return [int(part) if part.isdigit() else part for part in DIGITS.split(name)]


def pngs(folder: str, subdir: str) -> list[str]:
    """The PNG names of folder/subdir, in natural order; ToolError when there are none."""
    path = os.path.join(folder, subdir)
    if not os.path.isdir(path):
        raise ToolError("%s: no such folder (the %s images are expected there)" % (path, subdir))
    names = sorted((n for n in os.listdir(path) if n.lower().endswith(".png")), key=natural_key)
    if not names:
        raise ToolError("%s: no .png file in it" % path)
    for name in names:
        if any(c.isspace() for c in name):
            raise ToolError("%s: white space in the file name; the TUM lists cannot hold it"
                            % os.path.join(path, name))
    return names


def stamps_from_names(names: list[str]) -> Optional[list[float]]:
    """The stamps the names give, or None when some name is not a number of seconds."""
    stems = [name[:-4] for name in names]
    if not all(NUMBER.match(stem) for stem in stems):
        return None
    return [float(stem) for stem in stems]


def write_list(path: str, subdir: str, stamps: list[float], names: list[str]) -> None:
    """One `stamp subdir/name` line per image, stamps with 6 decimals."""
    with open(path, "w") as f:
        f.write("# written by dynvo_tools lists\n# timestamp filename\n")
        for stamp, name in zip(stamps, names):
            f.write("%.6f %s/%s\n" % (stamp, subdir, name))


def run(args: argparse.Namespace) -> int:
    """Writes the two lists; ToolError for a missing folder, no PNGs, or unequal counts when
    the names are not stamps."""
    if not args.fps > 0:
        raise ToolError("--fps must be > 0, got %s" % args.fps)
    outputs = [os.path.join(args.folder, name) for name in ("rgb.txt", "depth.txt")]
    for path in outputs:
        if os.path.exists(path) and not args.force:
            raise ToolError("%s exists; pass --force to replace it" % path)
    rgb, depth = pngs(args.folder, args.rgb), pngs(args.folder, args.depth)
    rgb_stamps, depth_stamps = stamps_from_names(rgb), stamps_from_names(depth)
    if rgb_stamps is None or depth_stamps is None:
        if len(rgb) != len(depth):
            raise ToolError("%d colour and %d depth images, and their names are not stamps: cannot pair them by order"
                            " (name them by their stamps, or give as many of each)" % (len(rgb), len(depth)))
        rgb_stamps = depth_stamps = [k / args.fps for k in range(len(rgb))]
        how = "by order, %g frames/s" % args.fps
    else:
        how = "from the file names"
    write_list(outputs[0], args.rgb, rgb_stamps, rgb)
    write_list(outputs[1], args.depth, depth_stamps, depth)
    print("lists: %d colour and %d depth images, stamps %s: %s, %s" % (len(rgb), len(depth), how, outputs[0],
                                                                       outputs[1]))
    if not os.path.exists(os.path.join(args.folder, "camera.json")):
        print("lists: note: no camera.json in %s; write one with your camera's intrinsics (docs/data.md), or"
              " give them with --set camera.source=custom --set camera.fx=..." % args.folder)
    return 0
