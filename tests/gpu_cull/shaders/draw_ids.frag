// Raster test: writes instance id + 1 into the R32_UINT target (0 = background).
#version 460

layout(location = 0) flat in uint v_instance;
layout(location = 0) out uint out_id;

void main() { out_id = v_instance + 1u; }
