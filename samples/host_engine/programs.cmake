# The host's programs: <name>[=<source>][:<MACRO>[,<MACRO>...]], each compiled to shaders/<name>.spv
# with every MACRO defined to 1. The sample's CMakeLists.txt builds them; tests/CMakeLists.txt embeds
# the same list for the node tests. host_content.h picks a program by its name.
set(host_engine_programs
  host_gbuffer.vert
  host_shadow.vert
  host_gbuffer.frag
  host_gbuffer_sample_rate.frag=host_gbuffer.frag:HOST_SAMPLE_RATE
  host_gbuffer_primitive.frag=host_gbuffer.frag:HOST_PRIMITIVE_ID
  host_gbuffer_primitive_sample_rate.frag=host_gbuffer.frag:HOST_SAMPLE_RATE,HOST_PRIMITIVE_ID
  host_surface_fill.frag=host_gbuffer.frag:HOST_SURFACE_FILL
  host_surface_fill_sample_rate.frag=host_gbuffer.frag:HOST_SAMPLE_RATE,HOST_SURFACE_FILL
  host_surface_visibility.frag
  host_surface_visibility_sample_rate.frag=host_surface_visibility.frag:HOST_SAMPLE_RATE
  host_visibility.frag
  host_accumulation.frag)
