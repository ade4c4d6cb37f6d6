# The library's sources, listed layer by layer in the order of README.md's layout (lowest
# first). A .cpp under src/ that no list names stops the configuration
# (bemcontact_check_source_lists), so a new file cannot be left out silently.
set(BEMCONTACT_CORE_SOURCES
  src/core/error.cpp
  src/core/limits.cpp
  src/core/types.cpp)
set(BEMCONTACT_QUADRATURE_SOURCES
  src/quadrature/gauss_legendre.cpp)
set(BEMCONTACT_GEOMETRY_SOURCES
  src/geometry/boundary.cpp
  src/geometry/mesh.cpp
  src/geometry/symmetry.cpp)
set(BEMCONTACT_KERNELS_SOURCES
  src/kernels/axisymmetric.cpp
  src/kernels/elliptic.cpp
  src/kernels/halfspace_ring.cpp
  src/kernels/kelvin2d.cpp
  src/kernels/ring_integrals.cpp)
set(BEMCONTACT_OPERATORS_SOURCES
  src/operators/bordered_lu.cpp
  src/operators/dense_lu.cpp
  src/operators/dense_subspaces.cpp
  src/operators/gmres.cpp
  src/operators/hmatrix.cpp)  # or hmatrix_unavailable.cpp without hmat-oss (CMakeLists.txt)
set(BEMCONTACT_REFERENCE_SOURCES
  src/reference/cantilever.cpp
  src/reference/circular_inclusion.cpp
  src/reference/curved_beam.cpp
  src/reference/flat_punch.cpp
  src/reference/fretting.cpp
  src/reference/hertz.cpp
  src/reference/kirsch.cpp
  src/reference/lame.cpp
  src/reference/pin_in_hole.cpp
  src/reference/plastic_cylinder.cpp
  src/reference/spence.cpp
  src/reference/stress_state.cpp
  src/reference/two_layer_ring.cpp
  src/reference/uniaxial_tension.cpp
  src/reference/wavy_contact.cpp
  src/reference/nonlocal_cattaneo.cpp
  src/reference/winkler.cpp)
set(BEMCONTACT_INTEGRATION_SOURCES
  src/integration/axisymmetric_element.cpp
  src/integration/plane_element.cpp
  src/integration/plane_element_quadrature.cpp)
set(BEMCONTACT_BEM_SOURCES
  src/bem/analysis.cpp
  src/bem/assembly.cpp
  src/bem/boundary_system.cpp
  src/bem/compressed_system.cpp
  src/bem/factored_body.cpp
  src/bem/postprocess.cpp
  src/bem/probe.cpp
  src/bem/resultants.cpp
  src/bem/rigid_modes.cpp)
set(BEMCONTACT_PLASTICITY_SOURCES
  src/plasticity/elastoplastic_region.cpp
  src/plasticity/initial_stress.cpp
  src/plasticity/j2_material.cpp)
set(BEMCONTACT_DD_SOURCES
  src/dd/balancing.cpp
  src/dd/decomposition.cpp
  src/dd/distribution.cpp
  src/dd/fibre_composite.cpp
  src/dd/interface.cpp
  src/dd/interface_operator.cpp
  src/dd/monolithic.cpp
  src/dd/plate_strips.cpp
  src/dd/solver.cpp)
set(BEMCONTACT_CONTACT_SOURCES
  src/contact/amplitude.cpp
  src/contact/condensed.cpp
  src/contact/contact_solver.cpp
  src/contact/contact_summary.cpp
  src/contact/free_motions.cpp
  src/contact/halfspace_model.cpp
  src/contact/newton_solver.cpp
  src/contact/nonlocal_friction.cpp
  src/contact/wear.cpp
  src/contact/model_routes.cpp
  src/contact/pairing.cpp
  src/contact/rigid_profile.cpp
  src/contact/rough_profile.cpp
  src/contact/thesis_solver.cpp
  src/contact/zone_ends.cpp
  src/contact/zone_refinement.cpp)
set(BEMCONTACT_IO_SOURCES
  src/io/file_names.cpp
  src/io/input/body_parser.cpp
  src/io/input/child_process.cpp
  src/io/input/contact_file.cpp
  src/io/input/decomposition_file.cpp
  src/io/input/expression.cpp
  src/io/input/gmsh_geometry.cpp
  src/io/input/parameter_overrides.cpp
  src/io/input/probe_input.cpp
  src/io/input/problem_file.cpp
  src/io/input/problem_reader.cpp
  src/io/input/problem_schema.cpp
  src/io/input/problem_text.cpp
  src/io/input/profile_file.cpp
  src/io/input/suggestions.cpp
  src/io/input/toml_reader.cpp
  src/io/output/contact_writer.cpp
  src/io/output/csv_table.cpp
  src/io/output/decomposition_writer.cpp
  src/io/output/json_writer.cpp
  src/io/output/output_directory.cpp
  src/io/output/probe_writer.cpp
  src/io/output/results_writer.cpp
  src/io/output/run_summary.cpp
  src/io/text_format.cpp)
set(BEMCONTACT_DRIVER_SOURCES
  src/driver/probe.cpp
  src/driver/resource_check.cpp
  src/driver/run.cpp)
set(BEMCONTACT_VALIDATION_SOURCES
  src/validation/axisymmetric_cases.cpp
  src/validation/case_support.cpp
  src/validation/cases.cpp
  src/validation/contact_cases.cpp
  src/validation/decomposition_cases.cpp
  src/validation/fretting_cases.cpp
  src/validation/multibody_cases.cpp
  src/validation/plane_cases.cpp
  src/validation/records.cpp
  src/validation/wavy_cases.cpp
  src/validation/compliance_cases.cpp
  src/validation/wear_cases.cpp)
set(BEMCONTACT_PARALLEL_SOURCES
  src/parallel/session.cpp)

set(BEMCONTACT_LIBRARY_LAYERS CORE QUADRATURE GEOMETRY KERNELS OPERATORS REFERENCE INTEGRATION BEM PLASTICITY DD CONTACT IO DRIVER)

function(bemcontact_check_source_lists)
  file(GLOB_RECURSE present RELATIVE ${PROJECT_SOURCE_DIR} CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/*.cpp)
  set(listed src/operators/hmatrix_unavailable.cpp)
  foreach(layer IN LISTS BEMCONTACT_LIBRARY_LAYERS ITEMS VALIDATION PARALLEL)
    list(APPEND listed ${BEMCONTACT_${layer}_SOURCES})
  endforeach()
  list(REMOVE_ITEM present ${listed})
  if(present)
    list(JOIN present "\n  " missing)
    message(FATAL_ERROR "sources under src/ that cmake/sources.cmake does not list:\n  ${missing}")
  endif()
endfunction()
