#pragma once
// The deck's solver section (docs/deck.md, "solver"), as values: the keys every method reads, and
// each method's own block (`solver.otm`). The deck parser (io/) fills them; a method's settings
// are built from them by the factory (solver/methods.cpp). The solver never sees the deck itself.
namespace kessler {

// How two bodies meet (docs/theory.md §3 and §11; deck `solver.contact`).
struct ContactSettings {
  enum class Kind {
    seizing,  // a body's points take the other body's carriers once within reach: the two stick
    sliding,  // a master surface of each body; the other's carriers are pushed back onto it and slide
  };
  Kind kind = Kind::seizing;
  double friction = 0.0;  // Coulomb coefficient of a sliding contact
  bool sliding() const { return kind == Kind::sliding; }
};

// What every method reads.
struct SolverSettings {
  double end_time = 0.0;  // s
  double cfl = 0.3;       // factor on the stable (CFL) time step
  long max_steps = 0;     // 0: no limit
  // Failure diagnosis (Method::check): the run stops when the time step falls below
  // min_dt_fraction of the initial one, or the total energy exceeds (1 + max_energy_growth) times
  // the initial total energy.
  double min_dt_fraction = 1e-3;
  double max_energy_growth = 0.1;
  // Debris contact: debris that reaches a body it may hit (not its own, nor one its body touched
  // before it was released) strikes it as matter. Without it, debris passes through every body (a
  // Whipple shield's rear wall would never be hit).
  bool debris_contact = true;
  ContactSettings contact;
  // Not deck keys (the theory fixes them; studies vary them):
  // eigenerosion (Pandolfi & Ortiz 2012; docs/theory.md §8): the radius of the ball B_eps as a
  // multiple of the point spacing h, also the ball over which released debris takes its velocity.
  double erosion_radius = 2.0;
};

// OTM's own keys, `solver.otm` (docs/theory.md §2–4, §8).
struct OtmOptions {
  // LME locality, beta = gamma / h^2: 4, the local end of Arroyo & Ortiz's range (0.8-4), gives
  // ~25 nodes per point instead of ~76 at 1.8, a third of the work and memory, and every
  // verification closer to its reference (docs/performance.md, docs/validation.md).
  double lme_gamma = 4.0;
  // Shape functions below this are cut off: r = h sqrt(-ln tol / gamma) (1.52 h at gamma 4).
  // 1e-4 instead of 1e-6: results within 1e-3 (docs/performance.md).
  double lme_tolerance = 1e-4;
  int min_neighbours = 12;  // enlarge the search radius until at least this many nodes
  // Seizing contact (docs/theory.md §3): the nodes of another body join a point's neighbourhood
  // only when that body's nearest node lies within contact_distance * h of the point. A point
  // sits about h/4 inside its own surface, so 1.0 couples across a gap of roughly h/2.
  double contact_distance = 1.0;
  // Volume averaging (F-bar over the nodal patch, solver/otm/volume_patch.hpp): the step's volume
  // change of each point is replaced by its nodal-patch average. Without it, strong shocks
  // overcompress scattered points (docs/theory.md §4).
  bool volume_averaging = true;
  // Visibility across cracks (docs/theory.md §8): a point does not take nodes of its own body that
  // lie behind broken material, so crack faces separate. Needed for brittle crack growth
  // (`griffith` converges with it, diverges without); off by default because with the scattered
  // erosion of a shocked impact target it leaves points one-sided neighbourhoods and the run
  // becomes unstable (measured on examples/sphere-plate.yaml).
  bool crack_visibility = false;
  // Not deck keys (the theory fixes them; studies vary them):
  // the volume averaging's stabilisation: a pressure -alpha rho c^2 d on the volume strain d that
  // the averaging took away (PointStore::volume_defect), alpha times the point's longitudinal
  // modulus, added to each point's own stress in the forces. With alpha = 1 the nodes feel each
  // point's whole volumetric stiffness (the averaged pressure on what the average keeps, the
  // stabilisation on what it takes away), so the averaged update has no zero-energy mode (the
  // crushed axis of a plastic Taylor bar) and no soft one, while the state the material sees
  // (density, pressure, heating) stays the patch average (docs/theory.md §4).
  double volume_stabilisation = 1.0;
  // The defect of an intact point relaxes with the time constant of this many wave transits of its
  // spacing, tau = k h / c (0: never), the energy it stored becomes heat, and the stored energy
  // follows the stiffness (docs/theory.md §4).
  double volume_relaxation = 10.0;
};

// SPH's constants (docs/theory.md §10). Not deck keys: the theory fixes them, studies vary them.
struct SphOptions {
  // Smoothing length h = smoothing * the particle's current spacing (support 2h): 1.2 gives 57
  // neighbours on a cubic lattice, the usual choice for solids.
  double smoothing = 1.2;
  // Monaghan's artificial viscosity (Monaghan, Annu. Rev. Astron. Astrophys. 30:543, 1992), its
  // linear coefficient alpha per particle by a switch after Cullen & Dehnen's (MNRAS 408:669, 2010;
  // sph::Integrator::switchViscosity): alpha rises at once towards viscosity_max where the forces
  // raise the compression, or the particle touches another body, and decays to viscosity_min over
  // viscosity_decay^-1 sound crossings of h; the quadratic coefficient is beta = viscosity_ratio *
  // alpha. A shock takes (1, 2), the standard pair; a smooth elastic wave or a smooth convergent
  // flow keeps a tenth of it.
  double viscosity_max = 1.0;
  double viscosity_min = 0.1;
  double viscosity_ratio = 2.0;
  double viscosity_decay = 0.2;
  // The artificial heat flux's coefficient alpha_u (Price, J. Comput. Phys. 227:10040, 2008; 1 as
  // there), over the pairs the viscosity acts on, at their closing speed (Noh, J. Comput. Phys.
  // 72:78, 1987: a contact's or a shock's start heats its first particles too much, and the flux
  // spreads that heat to their neighbours); 0: none.
  double heat_conduction = 1.0;
  // Monaghan's artificial stress against the tensile instability (Gray, Monaghan & Swift, CMAME
  // 190:6641, 2001): epsilon and the exponent n of f = W(r) / W(spacing).
  double artificial_stress = 0.3;
  int artificial_stress_exponent = 4;
  // The finite-element reconstruction (docs/theory.md §10): an element fails when the smallest
  // scaled Jacobian of its corners falls below this (0.2: a corner sheared to 11.5 degrees, a
  // shear strain of about 5, or inverted).
  double element_min_quality = 0.2;
  // The share of the deviatoric deformation and stress an intact lattice particle takes through its
  // reconstructed hexahedron (sph::ElementGradient; docs/theory.md §10), the rest through SPH's
  // pairs; 0: SPH alone. Half each: the hexahedra carry a surface's shear tractions to the particles
  // that bear them, and SPH's pairs hold the hexahedra's zero-energy modes.
  double element_share = 0.5;
};

// RKPM's options (docs/theory.md §12).
struct RkpmOptions {
  // The kernel's support radius in particle spacings: at 2, a point between particles of a cubic
  // lattice sees about 33 of them, and its linear basis stays well conditioned one layer inside a
  // surface or an edge.
  double support = 2.0;
  // A kernel update (docs/theory.md §12) when an intact particle's Green-Lagrange strain since the last
  // one, E = (F_inc^T F_inc - I) / 2, exceeds this in norm (sqrt(E:E)); 0 never updates. At 0.5 an
  // update comes at 36% compression along every axis, or a shear of 0.9.
  double update_strain = 0.5;
};

// A method's settings: what every method reads and each method's own block.
struct MethodSettings {
  SolverSettings solver;
  OtmOptions otm;
  SphOptions sph;
  RkpmOptions rkpm;
};

}  // namespace kessler
