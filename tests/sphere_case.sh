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

# The thick sphere octant with a closed form (A = 1, B = 2 mm, nu = 0.4999,
# p = 0.3 mu; objective: the mean u_x of the outer surface, w_B / 2 by
# symmetry), up to its Optimization subsection, which gets the further
# lines given; a test appends subsections of its own.
#   thick_sphere_case SOURCE_DIR OUTPUT_DIRECTORY ITERATIONS MESH_SIZE OPTIMIZATION_LINES
thick_sphere_case() {
  cat <<PRM
set Output directory = $2
set Print timings = false
subsection Output
  set VTU output = none
end
subsection Geometry
  set Mesh file = $1/meshes/sphere_octant.geo
  set Mesh size = $4
  set Dirichlet boundaries = 1: x; 2: y; 3: z
  set Pressure boundary ids = 4
  set Design boundary ids = 5
end
subsection Material
  set Young's modulus = 3
  set Poisson's ratio = 0.4999
end
subsection Loading
  set Pressure = 302
end
subsection Optimization
  set Maximum iterations = $3
  set Final analysis steps = 1
  set Design bound = 0.05
$5
end
subsection Objective 1
  set Direction field = constant
  set Direction = 1, 0, 0
  set Weight = 1
end
PRM
}
