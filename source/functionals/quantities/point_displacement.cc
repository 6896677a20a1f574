// A quantity is one file like this one: a class deriving from Quantity with
// declare_parameters() for its own entries, a constructor reading them, and
// value() with its partial derivatives; the registration line at the bottom.

#include <softopt/functionals/direction_field.h>
#include <softopt/functionals/quantity.h>
#include <softopt/shape/surface_nodes.h>

namespace softopt
{
  namespace
  {
    /**
     * u . v at one node of the surface: the travel of a fingertip, or of a
     * marker tracked on video, along the subsection's direction field v(X).
     * The node is the surface node nearest to "Point" in the initial
     * design X_o of the current mesh (nearest_surface_nodes(), which
     * "Tracked points" searches in X), so it stays the same node, and Q
     * differentiable, between mesh updates.
     */
    class PointDisplacement : public Quantity
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Point",
                          "0, 0, 0",
                          vector_pattern(),
                          "point displacement: the point whose displacement "
                          "is measured, in mm (replaced by the node of the "
                          "mesh on the body's surface nearest to it in the "
                          "initial design X_o of the current mesh: the mesh "
                          "as read, moved by the mesh updates).");
      }

      PointDisplacement(ParameterHandler  &prm,
                        const InputFile   &input,
                        const std::string &subsection,
                        const double       load_factor)
        : Quantity({load_factor})
        , point(parse_vector(prm.get("Point"), input.where(subsection, "Point")))
        , direction(DirectionFields::create(prm, input, subsection))
      {}

      double
      value(const HyperelasticProblem &problem,
            const DesignConfiguration &design,
            const States              &states,
            Derivatives               *derivatives) const override
      {
        const SurfaceNode node = nearest_surface_nodes(
          problem, design, design.ghosted(design.initial_coordinates()), {point})[0];
        const Tensor<1, 3> u = nodal_value(*states[0], node.displacement_dofs);
        const Point<3>     X(nodal_value(design.positions(), node.design_dofs));
        const Tensor<1, 3> v = direction->value(X);
        if (derivatives != nullptr)
          {
            // dQ/du = v at the node; dQ/dX_j = u_i dv_i/dX_j.
            const Tensor<1, 3> d_dX = transpose(direction->gradient(X)) * u;
            derivatives->d_da = {problem.create_vector()};
            derivatives->d_dX = design.create_vector();
            for (unsigned int c = 0; c < 3; ++c)
              {
                if (derivatives->d_da[0].in_local_range(node.displacement_dofs[c]))
                  derivatives->d_da[0](node.displacement_dofs[c]) = v[c];
                if (derivatives->d_dX.in_local_range(node.design_dofs[c]))
                  derivatives->d_dX(node.design_dofs[c]) = d_dX[c];
              }
            derivatives->d_da[0].compress(VectorOperation::insert);
            derivatives->d_dX.compress(VectorOperation::insert);
          }
        return u * v;
      }

    private:
      const Point<3>                        point;
      const std::unique_ptr<DirectionField> direction;
    };
  } // namespace

  SOFTOPT_REGISTER_QUANTITY(PointDisplacement,
                            "point displacement",
                            "u . v at the surface node nearest to \"Point\", "
                            "in mm (v the \"Direction field\").")
} // namespace softopt
