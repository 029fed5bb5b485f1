//! The renderer's queries: timestamps around the rendering passes of measured frames and one
//! pipeline-statistics query over a pass, each only where the device supports it.

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
    /// One timestamp before the first pass and one after each; `None` without timestamp
    /// support.
    pub(super) timestamps: Option<QueryPool>,
    /// How many queries `timestamps` holds.
    timestamp_count: u32,
    /// One pipeline-statistics query over the rendering pass; `None` without support.
    pub(super) statistics: Option<QueryPool>,
}

impl Queries {
    pub(super) fn new(device: &Arc<Device>) -> Result<Self> {
        let timestamps = if device.info.timestamps_supported {
            Some(timestamp_pool(device, 2)?)
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
            timestamp_count: 2,
            statistics,
        })
    }

    /// Makes room for `count` timestamps (a larger pool replaces the old one, which no
    /// pending submission uses: every frame is waited for).
    pub(super) fn ensure_timestamps(&mut self, device: &Arc<Device>, count: u32) -> Result<()> {
        if self.timestamps.is_some() && count > self.timestamp_count {
            self.timestamps = Some(timestamp_pool(device, count)?);
            self.timestamp_count = count;
        }
        Ok(())
    }

    /// Nanoseconds between consecutive timestamps of the last measured submission, which
    /// wrote `count` of them: one interval per pass.
    pub(super) fn read_timestamps(&self, device: &Device, count: u32) -> Result<Option<Vec<f64>>> {
        let Some(pool) = &self.timestamps else {
            return Ok(None);
        };
        let mut ticks = vec![0u64; count as usize];
        // SAFETY: the `count` queries were reset and written by the submission the fence waited for;
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
        let period = f64::from(info.timestamp_period_ns);
        let mask = if info.timestamp_valid_bits >= 64 {
            u64::MAX
        } else {
            (1u64 << info.timestamp_valid_bits) - 1
        };
        Ok(Some(
            ticks
                .windows(2)
                .map(|w| (w[1].wrapping_sub(w[0]) & mask) as f64 * period)
                .collect(),
        ))
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

/// A pool of `count` timestamp queries.
fn timestamp_pool(device: &Arc<Device>, count: u32) -> Result<QueryPool> {
    let info = vk::QueryPoolCreateInfo::default()
        .query_type(vk::QueryType::TIMESTAMP)
        .query_count(count);
    QueryPool::new(device, &info)
}
