#version 460
#extension GL_GOOGLE_include_directive : require
// Automatic exposure from the frame itself (runs between lighting and tonemap): a histogram of
// log2 luminance over every lit (non-background) pixel gives the log-average luminance and its
// 99.5th percentile. The exposure maps the log-average to middle grey (key 0.18, Reinhard et al.
// 2002) unless that would push the brightest 0.5 % past the tonemapper's white (exposure x L99.5
// <= kWhiteHeadroom, where the ACES fit gives about 0.94): rooms stay out of clipping by
// construction, the brightest 0.5 % (lamps' hot spots) excepted. The push's multiplier multiplies
// it (--exposure: compensation). No lit pixel: the multiplier alone.
// Two stages, two graph passes (a two-level reduction; the graph orders them):
//   0 histogram: size.z workgroups; each reduces its share of the pixels in shared memory and
//     writes its own slot (bins, log2 sum, count) of exposure_value: no atomics across
//     workgroups, nothing to clear between frames, the same result on every run.
//   1 resolve: one workgroup adds the slots (in slot order) and writes exposure_value[0].
#include "compute_bindings.glsl"

layout(local_size_x = kExposureGroupSize) in;
layout(push_constant) uniform Push { ExposurePush pc; };

const float kMinLog2 = -20.0, kMaxLog2 = 12.0;  // luminance 1e-6 .. 4096 (radiance units)
const float kKey = 0.18, kWhiteHeadroom = 4.0;
const uint kSlotBase = 4u;  // exposure_value[0..3]: the result (and 3 unused)
shared uint bins[kExposureBins];
shared float log_sum[kExposureGroupSize];
shared uint lit_count[kExposureGroupSize];

uint slot_at(uint group) { return kSlotBase + group * kExposureSlotFloats; }

// log_sum and lit_count over the workgroup, into element 0 (a fixed tree: deterministic).
void reduce_sums(uint t) {
  for (uint stride = kExposureGroupSize / 2u; stride > 0u; stride /= 2u) {
    barrier();
    if (t < stride) {
      log_sum[t] += log_sum[t + stride];
      lit_count[t] += lit_count[t + stride];
    }
  }
  barrier();
}

void histogram_stage(uint t) {
  for (uint b = t; b < kExposureBins; b += kExposureGroupSize) bins[b] = 0u;
  barrier();
  float sum = 0.0;
  uint count = 0u;
  uint pixels = pc.size.x * pc.size.y;
  uint step = kExposureGroupSize * pc.size.z;
  for (uint i = gl_WorkGroupID.x * kExposureGroupSize + t; i < pixels; i += step) {
    ivec2 px = ivec2(i % pc.size.x, i / pc.size.x);
    if (imageLoad(gbuffer_cell, px).r == kNoCell) continue;
    float lum = dot(imageLoad(hdr_image, px).rgb, vec3(0.2126, 0.7152, 0.0722));
    float l2 = clamp(log2(max(lum, 1e-6)), kMinLog2, kMaxLog2 - 1e-3);
    sum += l2;
    ++count;
    atomicAdd(bins[uint((l2 - kMinLog2) / (kMaxLog2 - kMinLog2) * float(kExposureBins))], 1u);
  }
  log_sum[t] = sum;
  lit_count[t] = count;
  reduce_sums(t);
  uint slot = slot_at(gl_WorkGroupID.x);
  for (uint b = t; b < kExposureBins; b += kExposureGroupSize) exposure_value[slot + b] = uintBitsToFloat(bins[b]);
  if (t == 0u) {
    exposure_value[slot + kExposureBins] = log_sum[0];
    exposure_value[slot + kExposureBins + 1u] = uintBitsToFloat(lit_count[0]);
  }
}

void resolve_stage(uint t) {
  uint groups = pc.size.z;
  for (uint b = t; b < kExposureBins; b += kExposureGroupSize) {
    uint n = 0u;
    for (uint g = 0u; g < groups; ++g) n += floatBitsToUint(exposure_value[slot_at(g) + b]);
    bins[b] = n;
  }
  float sum = 0.0;
  uint count = 0u;
  for (uint g = t; g < groups; g += kExposureGroupSize) {
    sum += exposure_value[slot_at(g) + kExposureBins];
    count += floatBitsToUint(exposure_value[slot_at(g) + kExposureBins + 1u]);
  }
  log_sum[t] = sum;
  lit_count[t] = count;
  reduce_sums(t);
  if (t != 0u) return;
  uint total = lit_count[0];
  float e = 1.0;
  if (total > 0u) {
    float average = exp2(log_sum[0] / float(total));
    // The 99.5th percentile: the top of the bin where the cumulative count passes 99.5 %.
    uint want = uint(ceil(0.995 * float(total))), seen = 0u, b = 0u;
    for (; b < kExposureBins; ++b) {
      seen += bins[b];
      if (seen >= want) break;
    }
    float l99 = exp2(kMinLog2 + float(min(b + 1u, kExposureBins)) * (kMaxLog2 - kMinLog2) / float(kExposureBins));
    e = min(kKey / max(average, 1e-6), kWhiteHeadroom / l99);
  }
  exposure_value[0] = e * pc.params.x;
}

void main() {
  if (pc.size.w == 0u)
    histogram_stage(gl_LocalInvocationID.x);
  else
    resolve_stage(gl_LocalInvocationID.x);
}
