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

# thick_sphere_case's objective from the incompressible closed form, in mm:
# lambda_a from p / mu = f(lambda_b) - f(lambda_a), f(s) = 2/s + 1/(2 s^4),
# lambda_b^3 = 1 + (lambda_a^3 - 1) (A/B)^3, and g_1 = (lambda_b - 1) B / 2.
thick_sphere_exact() {
  /usr/bin/python3 - <<'PY'
E, nu, p, A, B = 3.0, 0.4999, 0.302, 1.0, 2.0
mu = E / (2 * (1 + nu))
f = lambda s: 2 / s + 1 / (2 * s**4)
lb = lambda la: (1 + (la**3 - 1) * (A / B)**3) ** (1 / 3)
lo, hi = 1.0, 1.5
for _ in range(200):  # bisection: f(lb) - f(la) ascends in la
    m = (lo + hi) / 2
    lo, hi = (m, hi) if f(lb(m)) - f(m) < p / mu else (lo, m)
print("%.12g" % ((lb(lo) - 1) * B / 2))
PY
}
