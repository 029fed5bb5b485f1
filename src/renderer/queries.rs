//! The renderer's queries: two timestamps and one pipeline-statistics query around the
//! rendering pass of a measured frame, each only where the device supports it.

use std::sync::Arc;

use ash::vk;

use super::PipelineStats;
use crate::error::{vk_error, Result};
use crate::vk::objects::QueryPool;
use crate::vk::Device;

/// The statistics the query counts, in the order Vulkan writes them (ascending bits).
const STATISTICS: vk::QueryPipelineStatisticFlags = vk::QueryPipelineStatisticFlags::from_raw(
    vk::QueryPipelineStatisticFlags::INPUT_ASSEMBLY_VERTICES.as_raw()
        | vk::QueryPipelineStatisticFlags::INPUT_ASSEMBLY_PRIMITIVES.as_raw()
        | vk::QueryPipelineStatisticFlags::VERTEX_SHADER_INVOCATIONS.as_raw()
        | vk::QueryPipelineStatisticFlags::CLIPPING_INVOCATIONS.as_raw()
        | vk::QueryPipelineStatisticFlags::CLIPPING_PRIMITIVES.as_raw()
        | vk::QueryPipelineStatisticFlags::FRAGMENT_SHADER_INVOCATIONS.as_raw(),
);

/// The query pools a measured frame writes.
pub(super) struct Queries {
    /// Two timestamps around the rendering pass; `None` without timestamp support.
    pub(super) timestamps: Option<QueryPool>,
    /// One pipeline-statistics query over the rendering pass; `None` without support.
    pub(super) statistics: Option<QueryPool>,
}

impl Queries {
    pub(super) fn new(device: &Arc<Device>) -> Result<Self> {
        let timestamps = if device.info.timestamps_supported {
            let info = vk::QueryPoolCreateInfo::default()
                .query_type(vk::QueryType::TIMESTAMP)
                .query_count(2);
            Some(QueryPool::new(device, &info)?)
        } else {
            None
        };
        let statistics = if device.info.pipeline_statistics_query {
            // The device enables pipelineStatisticsQuery when it has it.
            let info = vk::QueryPoolCreateInfo::default()
                .query_type(vk::QueryType::PIPELINE_STATISTICS)
                .query_count(1)
                .pipeline_statistics(STATISTICS);
            Some(QueryPool::new(device, &info)?)
        } else {
            None
        };
        Ok(Queries {
            timestamps,
            statistics,
        })
    }

    /// Nanoseconds between the two timestamps of the last measured frame.
    pub(super) fn read_timestamps(&self, device: &Device) -> Result<Option<f64>> {
        let Some(pool) = &self.timestamps else {
            return Ok(None);
        };
        let mut ticks = [0u64; 2];
        // SAFETY: both queries were reset and written by the submission the fence waited for;
        // WAIT makes the call return only complete values.
        unsafe {
            device.raw.get_query_pool_results(
                pool.raw(),
                0,
                &mut ticks,
                vk::QueryResultFlags::TYPE_64 | vk::QueryResultFlags::WAIT,
            )
        }
        .map_err(vk_error("vkGetQueryPoolResults"))?;
        let info = &device.info;
        let mask = if info.timestamp_valid_bits >= 64 {
            u64::MAX
        } else {
            (1u64 << info.timestamp_valid_bits) - 1
        };
        let elapsed = ticks[1].wrapping_sub(ticks[0]) & mask;
        Ok(Some(elapsed as f64 * info.timestamp_period_ns as f64))
    }

    /// The pipeline statistics of the last measured frame.
    pub(super) fn read_statistics(&self) -> Result<Option<PipelineStats>> {
        let Some(pool) = &self.statistics else {
            return Ok(None);
        };
        let mut values = [[0u64; 6]];
        // SAFETY: the query was reset, begun and ended by the submission the fence waited
        // for; one query of six 64-bit counters fills `values`.
        unsafe {
            pool.device().raw.get_query_pool_results(
                pool.raw(),
                0,
                &mut values,
                vk::QueryResultFlags::TYPE_64 | vk::QueryResultFlags::WAIT,
            )
        }
        .map_err(vk_error("vkGetQueryPoolResults"))?;
        let [ia_vertices, ia_primitives, vs, clip_in, clip_out, fs] = values[0];
        Ok(Some(PipelineStats {
            input_assembly_vertices: ia_vertices,
            input_assembly_primitives: ia_primitives,
            vertex_shader_invocations: vs,
            clipping_invocations: clip_in,
            clipping_primitives: clip_out,
            fragment_shader_invocations: fs,
        }))
    }
}
