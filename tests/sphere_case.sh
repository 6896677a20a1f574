# Sourced by the script tests: a one-iteration design case on the coarse
# sphere octant (a few seconds), printed as a parameter file.
#   sphere_case MESH_FILE OUTPUT_DIRECTORY MESH_PARAMETERS PRESSURE
#               MAXIMUM_ITERATIONS CHECKPOINT_INTERVAL
sphere_case() {
  cat <<PRM
set Output directory = $2
set Print timings = false
subsection Output
  set VTU output = none
end
subsection Geometry
  set Mesh file = $1
  set Mesh size = 0.5
  set Mesh parameters = $3
  set Dirichlet boundaries = 1: x; 2: y; 3: z
  set Pressure boundary ids = 4
  set Design boundary ids = 5
end
subsection Material
  set Young's modulus = 3
  set Poisson's ratio = 0.49
end
subsection Loading
  set Pressure = $4
end
subsection Optimization
  set Maximum iterations = $5
  set Checkpoint interval = $6
  set Final analysis steps = 1
  set Design bound = 0.05
end
subsection Objective 1
  set Direction field = inward radial
end
PRM
}
