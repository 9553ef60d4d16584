// The transfer schemes, particle velocity updates and grid damping of mpmFsi (doc/methods/mpm.md
// sections 2.4, 2.6 and 7). The equations they select are applied in MpmSolver.cpp:
//
//   USL  (Sulsky, Chen & Schreyer 1994; the thesis, note 2.8): P2G m, mv, f with the stress of
//        the previous step -> grid solve -> G2P x, v -> L = sum_I v_I^{n+1} (x) grad N_Ip,
//        F <- (I + dt L) F, stress.
//   USF  (Bardenhagen 2002, "update stress first"): P2G m, mv -> v_I^n = (mv)_I / m_I ->
//        L = sum_I v_I^n (x) grad N_Ip, F, stress -> P2G f -> grid solve -> G2P x, v.
//   MUSL (Sulsky, Zhou & Schreyer 1995; Nairn 2003): USL, but L from the re-mapped velocity
//        v_I = sum_p N_Ip m_p v_p^{n+1} / m_I (grid boundary conditions applied to it again).
//
//   FLIP v_p += dt sum_I N_Ip a_I (the thesis); PIC v_p = sum_I N_Ip v_I^{n+1}; flipPic the
//        blend r FLIP + (1 - r) PIC; APIC (Jiang, Schroeder, Selle, Teran & Stomakhin 2015):
//        v_p = sum_I N_Ip v_I^{n+1}, C_p = B_p D_p^-1 with B_p = sum_I N_Ip v_I (x_I - x_p)^T and
//        D_p = sum_I N_Ip (x_I - x_p)(x_I - x_p)^T (dx^2/4 I for quadratic, dx^2/3 I for cubic
//        B-splines inside the grid; for linear hats B_p D_p^-1 = sum_I v_I (x) grad N_Ip
//        exactly, the form used since D_p is singular on a node), and the P2G momentum
//        m_p N_Ip (v_p + C_p (x_I - x_p)).
//
//   massProportional: a_I = (f_I - alpha_d (mv)_I) / m_I (note 2.4, the author's code's sign).
#include "mpm/MpmModels.hpp"

namespace mfdyn {

namespace {

class Usl final : public MpmScheme {
public:
    explicit Usl(const Dictionary&) {}
    StressUpdate stressUpdate() const override { return StressUpdate::last; }
};

class Usf final : public MpmScheme {
public:
    explicit Usf(const Dictionary&) {}
    StressUpdate stressUpdate() const override { return StressUpdate::first; }
};

class Musl final : public MpmScheme {
public:
    explicit Musl(const Dictionary&) {}
    StressUpdate stressUpdate() const override { return StressUpdate::modifiedLast; }
};

class Flip final : public VelocityUpdate {
public:
    explicit Flip(const Dictionary&) {}
    double flipFraction() const override { return 1.0; }
};

class Pic final : public VelocityUpdate {
public:
    explicit Pic(const Dictionary&) {}
    double flipFraction() const override { return 0.0; }
};

class FlipPic final : public VelocityUpdate {
public:
    static KeywordSchema keywords() {
        return KeywordSchema("velocityUpdate", "flipPic")
            .scalar("flipFraction", "-", "r in v = r FLIP + (1 - r) PIC (an entry of mpmProperties)")
            .atLeast(0)
            .atMost(1);
    }
    explicit FlipPic(const Dictionary& dict) : r_(keywords().read(dict).scalar("flipFraction")) {}
    double flipFraction() const override { return r_; }
    std::string describe() const override { return "flipPic (flipFraction " + std::to_string(r_) + ")"; }

private:
    double r_;
};

class Apic final : public VelocityUpdate {
public:
    explicit Apic(const Dictionary&) {}
    double flipFraction() const override { return 0.0; }
    bool affine() const override { return true; }
};

class NoDamping final : public GridDamping {
public:
    explicit NoDamping(const Dictionary&) {}
    double coefficient() const override { return 0.0; }
};

class MassProportional final : public GridDamping {
public:
    static KeywordSchema keywords() {
        return KeywordSchema("gridDamping", "massProportional")
            .scalar("dampingCoefficient", "1/s",
                    "alpha_d of the grid force -alpha_d (mv)_I (an entry of mpmProperties)")
            .atLeast(0);
    }
    explicit MassProportional(const Dictionary& dict)
        : alpha_(keywords().read(dict).scalar("dampingCoefficient")) {}
    double coefficient() const override { return alpha_; }
    std::string describe() const override {
        return "massProportional (dampingCoefficient " + std::to_string(alpha_) + " 1/s)";
    }

private:
    double alpha_;
};

}  // namespace

MFDYN_REGISTER(MpmScheme, Usl, "USL", "update stress last (Sulsky et al. 1994; the thesis)");
MFDYN_REGISTER(MpmScheme, Usf, "USF",
               "update stress first, from the velocity mapped to the grid (Bardenhagen 2002)");
MFDYN_REGISTER(MpmScheme, Musl, "MUSL",
               "modified USL: stress from the re-mapped updated velocity (Sulsky 1995)");
MFDYN_REGISTER(VelocityUpdate, Flip, "FLIP", "v_p += dt sum N a_I (the thesis)");
MFDYN_REGISTER(VelocityUpdate, Pic, "PIC", "v_p = sum N v_I (dissipative)");
MFDYN_REGISTER(VelocityUpdate, FlipPic, "flipPic", "r FLIP + (1 - r) PIC");
MFDYN_REGISTER(VelocityUpdate, Apic, "APIC", "affine PIC (Jiang et al. 2015): conserves angular momentum");
MFDYN_REGISTER(GridDamping, NoDamping, "none", "no grid damping");
MFDYN_REGISTER(GridDamping, MassProportional, "massProportional",
               "grid force -alpha_d (mv)_I (note 2.4; damping ratio alpha_d / (2 omega))");

}  // namespace mfdyn
