// The entries of the case file, one function per section, declared in the order --help lists
// them (input/case_file.h).
#include "input/case_file.h"

#include "input/analysis_declarations.h"
#include "input/spec_list.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace compliant
{
  using dealii::ParameterHandler;
  namespace Patterns = dealii::Patterns;

  void declare_geometry_parameters(ParameterHandler                     &prm,
                                   const std::vector<GeometryParameter> &geometry_parameters)
  {
    prm.enter_subsection("Parameters");
    for (const auto &p : geometry_parameters)
      prm.declare_entry(p.name, round_trip_text(p.value), Patterns::Double(),
                        p.help.empty() ? "Geometry parameter of the .geo file." : p.help);
    prm.leave_subsection();
  }

  namespace
  {
    // Model, Analysis and the entries each registered analysis declares for itself.
    void declare_model_and_analysis(ParameterHandler &prm)
    {
      prm.declare_entry("Model", "plane stress",
                        Patterns::Selection("plane stress|plane strain|3d"),
                        "Kinematic model: 2D plane stress (uses Material/Thickness), 2D plane "
                        "strain, or 3D solid. Must match the dimension of the mesh.");
      std::string names, documentation;
      if (registered_analyses().empty())
        throw std::logic_error("no analysis registered before the case was read");
      for (const auto &a : registered_analyses())
        {
          names += (names.empty() ? "" : "|") + a.name;
          documentation += " '" + a.name + "': " + a.documentation + ".";
        }
      prm.declare_entry("Analysis", "linear static", Patterns::Selection(names),
                        "Kind of analysis." + documentation);
      for (const auto &a : registered_analyses())
        a.declare_parameters(prm);
    }

    void declare_geometry_section(ParameterHandler                     &prm,
                                  const std::vector<GeometryParameter> &geometry_parameters)
    {
      prm.enter_subsection("Geometry");
      {
        prm.declare_entry("Mesh file", "",
                          Patterns::Anything(),
                          "A parametric gmsh .geo file (meshed at run time), a ready .msh file, or an "
                          "Abaqus/CalculiX .inp mesh (element and node sets and surfaces are the "
                          "group names; see README, Geometry). "
                          "Relative paths are looked up next to the case file, then in meshes/.");
        prm.declare_entry("Imperfection", "", Patterns::Anything(),
                          "Nonlinear static analyses: the geometry shifted by buckling mode shapes before "
                          "the run, '<mode>: <amplitude>[, <mode>: <amplitude> ...]' (e.g. '1: 0.01'). "
                          "The modes are those of Analysis = buckling on the perfect geometry under the "
                          "case's loads (settings from the Buckling subsection), each scaled so that its "
                          "largest displacement component is the amplitude (a length, any sign; where a "
                          "positive and a negative component are equally large, as in antisymmetric "
                          "modes, the one at the smallest x, then y, then z, takes the amplitude's sign). "
                          "A path that would meet a bifurcation then follows the buckled branch. Empty: "
                          "the perfect geometry.");
        prm.declare_entry("Maximum cells", "0", Patterns::Integer(0),
                          "The most cells the gmsh mesh of a .geo file may have. Before meshing, gmsh "
                          "meshes the curves and the cell count is estimated from them (exactly for "
                          "transfinite blocks); a larger mesh is refused with the geometry parameters "
                          "that asked for it (a length in the wrong unit asks for millions of times "
                          "more cells). 0: automatic, what the memory available holds at about 1 kB "
                          "per cell on each rank.");
        prm.declare_entry("Meshing time limit", "0", Patterns::Double(0),
                          "Seconds gmsh may take to read and mesh the geometry (it runs in a child "
                          "process, which is stopped at the limit and the run refused). 0: automatic, "
                          "60 s to read the geometry and mesh its curves, then 60 s + 100 us per "
                          "estimated cell.");
        declare_geometry_parameters(prm, geometry_parameters);
      }
      prm.leave_subsection();
    }

    void declare_discretization_section(ParameterHandler &prm)
    {
      prm.enter_subsection("Discretization");
      {
        prm.declare_entry("Element degree", "2", Patterns::Integer(1, 4),
                          "Polynomial degree of the displacement elements: 1 to 4 on quadrilaterals and "
                          "hexahedra, 1 or 2 on triangles and tetrahedra.");
        prm.declare_entry("Global refinements", "0", Patterns::Integer(0, 8),
                          "Uniform refinements of the gmsh mesh before solving.");
        prm.declare_entry("Formulation", "displacement", Patterns::Selection("displacement|mixed"),
                          "Linear static and modal analyses. mixed: displacement Q_k with a discontinuous "
                          "pressure P_(k-1) (Q2-P1 at degree 2), free of volumetric locking for "
                          "nearly incompressible materials (printed TPU, nu near 0.5); plane strain "
                          "and 3D, quadrilaterals/hexahedra, degree 2 or 3, solved by MUMPS. "
                          "Finite strain has its own Finite strain/Formulation.");
        prm.declare_entry("Integration", "full", Patterns::Selection("full|reduced"),
                          "Quadrature of the stiffness on quadrilaterals and hexahedra. full: p + 1 "
                          "Gauss points per direction at degree p (exact on straight cells). reduced: p "
                          "points, as CalculiX's C3D20R, kept free of zero-energy (hourglass) modes by "
                          "Hourglass stiffness times the fully integrated stiffness. A cell bending "
                          "under a varying moment then carries no parasitic shear, so cells many times "
                          "longer than thick are much softer and nearer the answer (a thin leaf in "
                          "torsion on 8 : 1 : 1 cells: energy error 2.9e-2 full, 3.4e-3 reduced at m = 2). "
                          "Linear and nonlinear static analyses (the finite-strain residual and tangent "
                          "alike) without the model ladder, degree 2 to 4, displacement formulation. Displacements, rotations, reactions, stiffnesses and energies "
                          "gain most; stresses are evaluated from the same field, and on coarse meshes "
                          "carry part of the stabilized hourglass modes (README, Speed).");
        prm.declare_entry("Hourglass stiffness", "0.03", Patterns::Double(0, 1),
                          "With Integration = reduced: the fraction e of the fully integrated stiffness "
                          "kept, K = (1 - e) K_reduced + e K_full. Larger is stiffer and closer to full "
                          "integration; near 0 the hourglass modes are barely held (0 is refused).");
        prm.declare_entry("Curved boundaries", "true", Patterns::Bool(),
                          "true: every curved boundary of the gmsh geometry (curves in 2D, "
                          "surfaces in 3D: circles, cylinders and spheres exactly, ellipses, "
                          "splines and CAD patches through samples of their parametrization) stays "
                          "on its shape: refinement puts new vertices on it and the cells touching "
                          "it are mapped with the element degree (isoparametric), so quadratic "
                          "elements keep their order on holes and notches. .msh meshes, and any "
                          "entity gmsh cannot evaluate, are straight-sided, as the log says. "
                          "false: every cell straight-sided.");
        prm.declare_entry("Curved mapping degree", "0", Patterns::Integer(0, 6),
                          "Degree of the geometry mapping of quadrilaterals and hexahedra on curved "
                          "boundaries. 0: the element degree (isoparametric). One above it "
                          "(superparametric, e.g. 3 with Element degree = 2) takes the boundary's "
                          "interpolation error out of stresses at strongly curved edges: at the tip of "
                          "an elliptical hole the quadratic boundary is blunter than the ellipse and "
                          "adds an h^2 stress error of the opposite sign to the field's, so Q2 shows no "
                          "clean order there until the mapping is cubic "
                          "(cases/verification/elliptical_hole.md). Straight-sided meshes are mapped "
                          "at degree 1, triangles and tetrahedra at 2 at most.");
        prm.declare_entry("Mesh partition", "auto", Patterns::Selection("auto|shared|distributed"),
                          "How the mesh is spread over MPI ranks. shared: every rank holds the "
                          "whole mesh and owns a METIS part. distributed: each rank holds only its "
                          "part (read and cut on rank 0), so the memory per rank falls as ranks "
                          "grow; static analyses only. auto: distributed from 2e5 estimated DoFs "
                          "on more than one rank where the analysis allows it, else shared.");
      }
      prm.leave_subsection();
    }

    void declare_material_section(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      {
        prm.declare_entry("Thickness", "1", Patterns::Double(0),
                          "Out-of-plane thickness of 2D models; forces and energies are totals "
                          "over this thickness.");
        prm.declare_entry("Unit system", "SI", Patterns::Selection("SI|mm-N-MPa"),
                          "Units of the case. Library materials are stored in SI and converted: "
                          "mm-N-MPa gives E in MPa, density in t/mm^3.");
        prm.declare_entry("Materials", "*: steel", Patterns::Anything(),
                          "Material of each physical body: 'name: library_material [, E=..., "
                          "nu=..., density=..., yield=...]; ...'. '*' means every body. Library: "
                          "see the materials table in --help.");
      }
      prm.leave_subsection();
    }

    void declare_boundary_conditions_section(ParameterHandler &prm)
    {
      prm.enter_subsection("Boundary conditions");
      {
        prm.declare_entry("Clamped", "", Patterns::Anything(),
                          "Boundaries with all displacement components zero: 'left, right'.");
        prm.declare_entry("Displacement", "", Patterns::Anything(),
                          "Prescribed displacement per component: 'right: y=0.1; top: x=0, z=0'. "
                          "Components not named stay free. A value may be an expression of x, y, z, e.g. "
                          "'outer: x=1e-3*(x+y/2), y=1e-3*(y+x/2)'.");
        prm.declare_entry("Rotation", "", Patterns::Anything(),
                          "Prescribed rigid rotation of a boundary: 'right: degrees=1 (or angle=rad), "
                          "center=x y z, axis=0 0 1'. In 2D the axis is z. The exact rotation is "
                          "imposed (not its small-angle form). Coordinates may be expressions of geometry "
                          "parameters: center=l/2 0.");
        prm.declare_entry("Rigid", "", Patterns::Anything(),
                          "Boundaries that move as rigid bodies loaded by a force and a moment, "
                          "their translation and rotation unknowns (a torque drive, a pure end "
                          "moment): 'right: moment=M (2D, about z) or moment=Mx My Mz (3D), "
                          "force=Fx Fy [Fz], center=x y [z]'. The moment acts about the center "
                          "(default: the centroid of the boundary's nodes), which moves with the "
                          "boundary; force and moment keep their direction (dead loads), are totals "
                          "over the thickness in 2D and scale with the load factor; numbers or expressions of "
                          "geometry parameters. Exact rigid "
                          "motion at finite strain (any rotation). Gives rigid_rotation_<name>_<z|x y "
                          "z> (radians) and rigid_displacement_<name>_<x|y|z> (of the center). "
                          "Linear and nonlinear static analyses; a rigid boundary shares no node "
                          "with a supported boundary.");
      }
      prm.leave_subsection();
    }

    void declare_loads_section(ParameterHandler &prm)
    {
      prm.enter_subsection("Loads");
      {
        prm.declare_entry("Traction", "", Patterns::Anything(),
                          "Traction vector (force per area) on boundaries: 'top: 0 -1 0'.");
        prm.declare_entry("Total force", "", Patterns::Anything(),
                          "Total force spread uniformly over a boundary: 'right: 0 -1'.");
        prm.declare_entry("Pressure", "", Patterns::Anything(),
                          "Pressure (force per area) normal to boundaries, positive pushing on the "
                          "body (against the outward normal): 'inner: 2; outer: 0.5*(1+y/10)', a "
                          "number or an expression of x, y, z and geometry parameters. On the "
                          "undeformed boundary: linear analyses; at finite strain use Finite "
                          "strain/Follower pressure.");
        prm.declare_entry("Body force", "", Patterns::Anything(),
                          "Force per volume on every body: '0 -9.81 0'.");
        prm.declare_entry("Gravity", "", Patterns::Anything(),
                          "Acceleration of gravity: body force = density * gravity.");
      }
      prm.leave_subsection();
    }

    void declare_linear_solver_section(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      {
        prm.declare_entry("Method", "auto", Patterns::Selection("auto|matrix-free|cg-amg|direct"),
                          "auto: matrix-free for degree >= 2 on quadrilaterals/hexahedra in linear "
                          "static analyses, else MUMPS below 30000 DoFs, else cg-amg; an iterative "
                          "solve that fails to converge in 300 iterations is redone with MUMPS (the "
                          "log says so). matrix-free: CG on the operator without a stored matrix, "
                          "preconditioned by a p-multigrid (degree p..1, Chebyshev smoothing) with "
                          "PETSc GAMG on degree 1 (linear static, quadrilaterals/hexahedra; "
                          "otherwise cg-amg is used and the log says so). cg-amg: conjugate gradients "
                          "with PETSc GAMG on the assembled matrix, given its block size and the "
                          "rigid-body modes. direct: MUMPS LU.");
        prm.declare_entry("Relative tolerance", "1e-10", Patterns::Double(0, 1),
                          "Residual reduction of the iterative solver.");
        prm.declare_entry("Maximum iterations", "2000", Patterns::Integer(1),
                          "Iterations before the iterative solver gives up.");
        prm.declare_entry("PETSc options", "", Patterns::Anything(),
                          "Extra PETSc options, e.g. '-pc_gamg_threshold 0.02'.");
        prm.declare_entry("Coarse space", "auto", Patterns::Selection("auto|degree-1"),
                          "Lowest level of the matrix-free p-multigrid. auto: on cells more than 3 "
                          "times longer than thick in thin parts (at most twice as thick across a "
                          "cell as it is long; no hanging nodes), the long-edge space below degree "
                          "2: quadratic along each cell's long edges and linear across, which holds "
                          "the bending modes that degree 1 locks on, factored by MUMPS (thin torsion "
                          "bar, 12:1 cells: 12 iterations instead of 34); degree 1 where long cells "
                          "lie in thick parts (a block meshed in slabs) or none are long. "
                          "degree-1: always the degree-1 level (MUMPS on long cells, else GAMG).");
      }
      prm.leave_subsection();
    }

    void declare_quantities_section(ParameterHandler &prm)
    {
      prm.enter_subsection("Quantities");
      {
        prm.declare_entry("Points", "", Patterns::Anything(),
                          "Named points for displacement output: 'tip: 48 60; mid: 24 52'. "
                          "Gives displacement_<name>_<x|y|z>. Coordinates may be expressions of geometry "
                          "parameters: 'p1: 0.4*L H/4 0'.");
        prm.declare_entry("Reactions", "", Patterns::Anything(),
                          "Boundaries whose reaction force and moment are reported, with the moment "
                          "point (default: origin; rotation-driven boundaries: the rotation "
                          "center): 'left; right: 100 5 0'.");
        prm.declare_entry("Mean displacements", "", Patterns::Anything(),
                          "Boundaries whose average displacement is reported: 'right, top'.");
        prm.declare_entry("Rotations", "", Patterns::Anything(),
                          "Boundaries whose best-fit rigid rotation is reported: 'right'. Gives "
                          "rotation_<b>_<x|y|z> (radians; 2D: _z), the rotation of the rigid motion "
                          "t + w x x closest to u over the boundary in the least-squares sense "
                          "(integrated over its area, independent of where the mesh puts nodes).");
        prm.declare_entry("Stress points", "", Patterns::Anything(),
                          "Named points for stress output: 'hole: 10 0; root: L/2 H/2'. Gives "
                          "stress_<name>_<xx|yy|zz|xy[|xz|yz]> (Cauchy, from the stress field "
                          "recovered by L2 projection onto continuous elements of the displacement's "
                          "degree), von_mises_<name>, principal_stress_<name>_<1|2|3> (largest "
                          "first), and the components and von Mises with the suffix _raw (from the "
                          "displacement gradient in the cell holding the point: discontinuous "
                          "between cells).");
        prm.declare_entry("Region maxima", "", Patterns::Anything(),
                          "Bodies (physical groups of full dimension) whose peak strain and stress "
                          "are reported with where they occur: 'flexure_A, flexure_B' ('*': every "
                          "body). Gives max_principal_strain_in_<body> (largest principal strain: "
                          "small strain in linear analyses, engineering lambda_1 - 1 at finite "
                          "strain; in-plane in 2D), max_von_mises_in_<body> and the reference "
                          "coordinates of each (_x, _y, _z), sampled at quadrature points and "
                          "element nodes; per step in a nonlinear curve.csv. Linear static, "
                          "linkage and nonlinear static analyses.");
        prm.declare_entry("Error estimates", "false", Patterns::Bool(),
                          "Linear static and modal: each quantity's (modal: each frequency's) "
                          "discretization error, estimated by the "
                          "dual-weighted residual with the dual at one degree more than the element's "
                          "(one extra solve on the same mesh serves every quantity), reported "
                          "beside its value as <name>_error_estimate (relative) and "
                          "<name>_error_estimate_absolute. Peaks at sharp corners have no converged "
                          "value: their estimate says how far the value still moves.");
        prm.declare_entry("Derived", "", Patterns::Anything(),
                          "Quantities computed from others with muparser: "
                          "'J = reaction_moment_right_x / (G * twist)'. Names of quantities, "
                          "geometry parameters, E, nu, G and thickness may be used.");
      }
      prm.leave_subsection();
    }

    void declare_comparison_section(ParameterHandler &prm)
    {
      prm.enter_subsection("Comparison");
      {
        prm.declare_entry("Checks", "", Patterns::Anything(),
                          "Quantities compared with closed forms: "
                          "'displacement_tip_y ~ timoshenko_cantilever_deflection(P=1, L=L, ...); ...'. "
                          "Arguments are muparser expressions of geometry parameters, E, nu, G, "
                          "thickness and quantities. See the closed-form list in --help.");
      }
      prm.leave_subsection();
    }

    void declare_output_section(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      {
        prm.declare_entry("Directory", "", Patterns::Anything(),
                          "Where results go; empty: results/<case file name>.");
        prm.declare_entry("Fields", "true", Patterns::Bool(),
                          "Write HDF5 + XDMF fields (displacement, strain, stress, von Mises, "
                          "material and partition id) for ParaView.");
        prm.declare_entry("Pictures", "true", Patterns::Bool(),
                          "Draw the result beside summary.json and write report.html, a "
                          "self-contained page for a design review (case, model, mesh, solver, "
                          "quantities with their estimates, closed-form comparisons and warnings, "
                          "pictures, timings). picture.svg: the deformed part coloured by von Mises "
                          "with the peak marked and the undeformed part behind (magnified, the "
                          "factor printed, when displacements are small; 3D: two views drawn "
                          "in-process); modal runs: mode_<k>.svg per mode; nonlinear static runs: "
                          "also load_displacement.svg from curve.csv.");
      }
      prm.leave_subsection();
    }
  } // namespace

  void declare_case_parameters(ParameterHandler                     &prm,
                               const std::vector<GeometryParameter> &geometry_parameters)
  {
    declare_model_and_analysis(prm);
    declare_geometry_section(prm, geometry_parameters);
    declare_discretization_section(prm);
    declare_material_section(prm);
    declare_boundary_conditions_section(prm);
    declare_loads_section(prm);
    declare_linear_solver_section(prm);
    declare_quantities_section(prm);
    declare_comparison_section(prm);
    declare_output_section(prm);
  }
} // namespace compliant
