#pragma once
// Buoyancy: a fluid fills the half-plane y < surface_y. Each dynamic box and each particle disk
// (radius > 0) feels the upward force ρ·A_sub·|g| of the fluid it displaces, applied at the
// centroid of its submerged part, so a box that tilts is turned by the lift (it rights itself
// when its shape is stable, like a flat raft, and settles corner-down when it is not, like a
// square log of half the fluid's density). Boxes are clipped against the surface at any angle;
// disks use the circular segment in closed form.
//
// Energy. The lift is conservative even for a turning box: U = ρ·|g|·∫_sub (surface_y − y) dA
// = ρ·|g|·A_sub·(surface_y − ȳ_sub), the first moment of the submerged part about the surface.
// Its gradient is exactly the force (−∂U/∂Y = ρ·|g|·A_sub because moving the body only
// moves the waterline, where the integrand is 0) and the torque
// (−∂U/∂θ = ρ·|g|·A_sub·(x̄_sub − X)).
// So the lift is booked as potential energy, not as work, and the drift keeps measuring the
// integrator alone. (Booking it as power F·v would also balance, but would hide a method that
// pumps energy into a bobbing box inside work_nc.)
//
// Fluid drag, the only non-conservative part (its power enters work_nc): −b_f·φ·v on the centre
// and −b_f·φ·(I/m)·ω on the spin, with φ = A_sub/A the submerged fraction. Scaling by φ makes
// the drag grow smoothly as a body enters the water instead of switching on at the surface (a
// step that adaptive and high-order methods would see as a kink); the I/m factor damps the
// spin at the same rate b_f·φ/m as the motion, so a tilted raft settles as fast as it stops
// bobbing. A particle of radius 0 has no area: it feels no lift, and its drag is b_f·v below
// the surface and 0 above.
//
// Jacobians: the exact stiffness of the lift (its Hessian, symmetric since it is conservative)
// and the drag's damping with φ held fixed (its dependence on the position is left out, as
// Baraff & Witkin leave out a damper's dependence on direction: Newton's residual stays exact).

#include "physics/effects/Effect.h"

#include <vector>

namespace phasebox {

struct RigidBody;

// The part of a body below the surface, relative to the body's centre.
struct SubmergedPart {
    double area = 0.0;
    Vec2 centroid = Vec2::Zero();  // of the submerged part, from the body's centre
    // The waterline, where the surface cuts the body: x from the centre at both ends
    // (waterlineFrom ≤ waterlineTo); empty (both 0) when the body is dry or fully under.
    double waterlineFrom = 0.0, waterlineTo = 0.0;

    double waterlineLength() const { return waterlineTo - waterlineFrom; }
};

class BuoyancyEffect final : public Effect {
public:
    // gravity is |g| of the scene's gravity effect, which buoyancy needs (validateScene says so).
    BuoyancyEffect(double fluidDensity, double surfaceY, double drag, double gravity);

    double addForces(double t, const Vec& q, const Vec& u, Vec& force) override;
    double nonConservativePower(double t, const Vec& q, const Vec& u) override;
    void addJacobians(double t, const Vec& q, const Vec& u, ForceJacobians& jacobians) override;
    double potentialEnergy(const Vec& q) const override;
    bool hasNonConservativePart() const override { return drag_ > 0.0; }
    void bind(const EffectWorldView& view) override;

    // A box of half size (hx, hy) turned by angle, whose centre is `depth` below the surface
    // (depth = surface_y − Y; negative when the centre is above it).
    static SubmergedPart submergedBox(const Vec2& halfSize, double angle, double depth);
    // A disk of this radius whose centre is `depth` below the surface.
    static SubmergedPart submergedDisk(double radius, double depth);
    // A convex polygon's (corners counter-clockwise about its centroid, of this area).
    static constexpr int kMaxVertices = 16;
    static SubmergedPart submergedPolygon(const std::vector<Vec2>& vertices, double area,
                                          double angle, double depth);

    double fluidDensity() const { return density_; }
    double surfaceY() const { return surfaceY_; }

private:
    // Calls fn(dof, isRigid, part, fullArea) for every dynamic body in state q.
    template <typename Fn>
    void forEachBody(const Vec& q, Fn&& fn) const;

    double density_, surfaceY_, drag_, gravity_;
    std::vector<double> diskRadius_;              // per dynamic particle
    std::vector<Vec2> boxHalfSize_;               // per dynamic box
    std::vector<double> rigidDiskRadius_;         // per dynamic box: a disk's radius, 0 for a box
    std::vector<const RigidBody*> rigidPolygon_;  // per dynamic box: a polygon's record, or null
    std::vector<double> rigidPolygonArea_;        // and its area
};

}  // namespace phasebox
