#version 460
#extension GL_GOOGLE_include_directive : require
// Automatic exposure from the frame itself (one workgroup; runs between lighting and tonemap):
// a histogram of log2 luminance over the lit (non-background) pixels gives the log-average
// luminance and its 99.5th percentile. The exposure maps the log-average to middle grey (key 0.18,
// Reinhard et al. 2002) unless that would push the brightest 0.5 % past the tonemapper's white
// (exposure x L99.5 <= kWhiteHeadroom, where the ACES fit gives about 0.94): rooms stay out of
// clipping by construction, the brightest 0.5 % (lamps' hot spots) excepted. The push's exposure multiplies it
// (--exposure: compensation). No lit pixel: the multiplier alone.
#include "compute_bindings.glsl"

layout(local_size_x = kExposureGroupSize) in;
layout(push_constant) uniform Push { ExposurePush pc; };

const uint kBins = 128u;
const float kMinLog2 = -20.0, kMaxLog2 = 12.0;  // luminance 1e-6 .. 4096 (radiance units)
const float kKey = 0.18, kWhiteHeadroom = 4.0;
shared uint bins[kBins];
shared float log_sum[kExposureGroupSize];
shared uint lit_count[kExposureGroupSize];

void main() {
  uint t = gl_LocalInvocationID.x;
  for (uint b = t; b < kBins; b += kExposureGroupSize) bins[b] = 0u;
  barrier();
  float sum = 0.0;
  uint count = 0u;
  uint pixels = pc.size.x * pc.size.y;
  for (uint i = t; i < pixels; i += kExposureGroupSize * pc.size.z) {
    ivec2 px = ivec2(i % pc.size.x, i / pc.size.x);
    if (imageLoad(gbuffer_cell, px).r == kNoCell) continue;
    float lum = dot(imageLoad(hdr_image, px).rgb, vec3(0.2126, 0.7152, 0.0722));
    float l2 = clamp(log2(max(lum, 1e-6)), kMinLog2, kMaxLog2 - 1e-3);
    sum += l2;
    ++count;
    atomicAdd(bins[uint((l2 - kMinLog2) / (kMaxLog2 - kMinLog2) * float(kBins))], 1u);
  }
  log_sum[t] = sum;
  lit_count[t] = count;
  barrier();
  if (t != 0u) return;
  float total_log = 0.0;
  uint total = 0u;
  for (uint k = 0u; k < kExposureGroupSize; ++k) {
    total_log += log_sum[k];
    total += lit_count[k];
  }
  float e = 1.0;
  if (total > 0u) {
    float average = exp2(total_log / float(total));
    // The 99.5th percentile: the top of the bin where the cumulative count passes 99.5 %.
    uint want = uint(ceil(0.995 * float(total))), seen = 0u, b = 0u;
    for (; b < kBins; ++b) {
      seen += bins[b];
      if (seen >= want) break;
    }
    float l99 = exp2(kMinLog2 + float(min(b + 1u, kBins)) * (kMaxLog2 - kMinLog2) / float(kBins));
    e = min(kKey / max(average, 1e-6), kWhiteHeadroom / l99);
  }
  exposure_value[0] = e * pc.params.x;
}
