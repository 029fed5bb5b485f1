//! A draw's GL primitive mode as the Vulkan topology it is drawn with.

use ffvk::Topology;

use super::invalid;
use crate::enums::*;
use crate::result::FfvkResult;

/// The topology of `mode`: the six Vulkan has, and `GL_TRIANGLES_ADJACENCY` for GL's polygons
/// with their edge flags (`ffvkEdgeFlaggedIndices`); the four GL has beside them are refused
/// with what to do (turn them into lists with `ffvkPrimitiveIndices`).
pub(super) fn topology(mode: u32) -> Result<Topology, FfvkResult> {
    Ok(match mode {
        GL_POINTS => Topology::PointList,
        GL_LINES => Topology::LineList,
        GL_LINE_STRIP => Topology::LineStrip,
        GL_TRIANGLES => Topology::TriangleList,
        GL_TRIANGLE_STRIP => Topology::TriangleStrip,
        GL_TRIANGLE_FAN => Topology::TriangleFan,
        // GL 3.2's triangles with adjacency, as ffvkEdgeFlaggedIndices makes them: GL's
        // polygons with their edge flags.
        GL_TRIANGLES_ADJACENCY => Topology::EdgeFlaggedTriangles,
        GL_LINE_LOOP | GL_QUADS | GL_QUAD_STRIP | GL_POLYGON => {
            return Err(invalid(format!(
                "ffvkDraw: mode {} is drawn as a list: turn its vertices into indices with ffvkPrimitiveIndices (or ffvkPrimitiveIndicesRange) and draw those",
                mode_name(mode)
            )))
        }
        other => {
            return Err(invalid(format!(
                "ffvkDraw: mode {} is not a GL primitive: expected GL_POINTS, GL_LINES, GL_LINE_STRIP, GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN or GL_TRIANGLES_ADJACENCY (from ffvkEdgeFlaggedIndices)",
                enum_name(other)
            )))
        }
    })
}
