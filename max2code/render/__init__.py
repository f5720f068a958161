"""Pictures of a simulation: PNG frames, animated GIF and MP4, SVG of one frame, a live window.

The data interface is `max2code.render.model` (bodies, poses, frames, a view): it imports nothing
beyond the standard library, so the engine can build frames without Pillow installed. The
writers import Pillow / imageio only when called (pip install 'max2code[render]').
"""

from .model import (Body, Capsule, Circle, Compound, Contact, Frame, Polygon, Pose,
                    RenderModelError, Segment, Shape, Style, View, colour, shape_from_parts,
                    shape_from_vertices)
from .fit import fit_view, world_extent
from .write import (RenderUnavailable, save, write_gif, write_mp4, write_png, write_png_dir,
                    write_svg)

__all__ = ["Body", "Capsule", "Circle", "Compound", "Contact", "Frame", "Polygon", "Pose", "RenderModelError",
           "RenderUnavailable", "Segment", "Shape", "Style", "View", "fit_view", "save",
           "world_extent", "write_gif", "colour", "shape_from_parts", "shape_from_vertices", "write_mp4", "write_png", "write_png_dir", "write_svg"]
