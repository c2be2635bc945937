camera { aperture 1 blur_samples 1e300 }
light_source { 0, 1 area_light x, y, 1e300, -1e300 adaptive 1e300 }
global_settings { max_trace_level 1e300 }
