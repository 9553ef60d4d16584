// contact `multiField` (Contact.hpp): a node field per body and a contact law between them.
// Bardenhagen, Guilkey, Roessig, Brackbill, Witzel & Foster 2001, "An improved contact algorithm
// for the material point method and application to stress propagation in granular material",
// CMES 2(4) 509-522 (eqs. 19-27); Nairn 2013, "Modeling imperfect interfaces in the material
// point method using multimaterial methods", CMES 92(3) 271-299 (the position check).
//
// At a node I where bodies a, b, ... have mass m_aI >= massCutoff (the solver has solved each
// body's momentum on its own field, v_aI the velocity after the force):
//
//   centre of mass     v_cm = sum_b m_bI v_bI / sum_b m_bI
//   normals            n_a = g_a / |g_a|, g_a = sum_p m_p grad N_I(x_p) over a's particles: each
//                      term points from the particle towards the node (N_I grows towards x_I),
//                      so at a's boundary g_a points out of a, and n_a is a's OUTWARD normal (the
//                      sign convention of this file); the pair normal of a against b is
//                      n_ab = (n_a - n_b) / |n_a - n_b|, and n_ba = -n_ab exactly (floating-point
//                      subtraction is antisymmetric), so the corrections of a and b are equal and
//                      opposite momenta: m_a dv_a = -m_b dv_b to round-off.
//   approaching        w_a = v_aI - v_cm, d_a = w_a . n_ab > 0 (a moves towards b relative to the
//                      centre of mass); a separating pair is left alone (no sticking, no tension)
//   position check     optional (`separation s`, Nairn 2013): contact only where the bodies'
//                      nodal centres of mass x_a = sum N m x / m_aI are closer than s cells along
//                      the normal, (x_b - x_a) . n_ab < s dx; without it (Bardenhagen 2001) any
//                      shared node of approaching bodies is in contact, one to two cells early
//                      as the single field is (note 6.3)
//   volume check       optional (`volumeFraction f`): contact only where the bodies' nodal volumes
//                      fill the node's support, (V_aI + V_bI) >= f dx^d with V_bI = sum_p N_Ip V_p:
//                      as sum_I N_I = 1 and int N_I dV = dx^d, two bodies that touch (no gap) fill
//                      it exactly, V_aI + V_bI = dx^d, whatever the shape function and wherever the
//                      node lies; a gap leaves it short, an overlap over. f = 1 is contact at
//                      touching. Short of 1 also where the support reaches past a free surface (a
//                      waterline) or past the grid's edges (the folded edge functions), so there
//                      the check waits for overlap.
//   surface-gap check  optional (`surfaceGap yes`, issue 18's float): contact only where the two
//                      bodies' surfaces touch or overlap, each surface located along n_ab from the
//                      body's nodal centre of mass through the shape function's half-space profile
//                      (HalfSpaceProfile.cpp): c_a = (x_a - x_I) . n_ab / h_n, s_a = c^-1(c_a),
//                      s_b = -c^-1(-c_b), contact where s_b - s_a <= 0, with h_n = |diag(h) n_ab|
//                      the cell's width along the normal. No parameter: touching half-spaces give
//                      s_b = s_a for any shape function, and unlike the volume check a free
//                      surface cutting the support across the normal (a waterline) leaves the
//                      centres, and so the gap, unchanged; unlike the position check's fixed
//                      distance, the touching distance c_b - c_a follows the node's place (0.81
//                      cells with quadratic B-splines at a node on the interface, up to 1.5 off it)
//   normal             dv_a = -d_a n_ab                 (the normal relative velocity removed)
//   Coulomb friction   t_a = w_a - d_a n_ab;  dv_a -= min(mu d_a, |t_a|) t_a / |t_a|
//                      (stick when |t_a| <= mu d_a; mu = 0 frictionless)
//   update             v_aI += dv_a, a_aI += dv_a / dt (so FLIP, which takes the acceleration,
//                      sees the same correction as the positions and PIC)
//   contact force      F_ab = sum_I m_aI dv_a / dt, the force on a from b (reported per pair)
//
// More than two bodies at a node: each body is paired with the heaviest other body there (its
// normal and friction), against the common v_cm; momentum is then exact only for two.
// Limits: the normals are the grid's (smeared over a cell), so a corner sees an averaged normal;
// the contact force has no adhesion (no tension across the interface), and no interface
// stiffness (the imperfect interfaces of Nairn 2013).
#include "mpm/contact/MultiFieldContact.hpp"

#include "core/Parallel.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace mfdyn {

namespace {

KeywordSchema pairKeywords() {
    return KeywordSchema("contact", "multiFieldCoeffs/pairs")
        .words("bodies", "the two bodies (particleGen regions) of the pair")
        .scalar("friction", "-", "the pair's Coulomb coefficient mu (0: frictionless)")
        .atLeast(0);
}

KeywordSchema coeffKeywords() {
    return KeywordSchema("contact", "multiFieldCoeffs")
        .scalar("friction", "-", "Coulomb coefficient mu of every pair not in `pairs` (0: frictionless)")
        .atLeast(0)
        .orDefault(0.0)
        .scalar("separation", "cells",
                "position check (Nairn 2013): contact only where the bodies' nodal centres of mass are "
                "closer than this along the normal; none: every shared node of approaching bodies")
        .greaterThan(0)
        .optional()
        .scalar(
            "volumeFraction", "-",
            "volume check: contact only where the bodies' nodal volumes sum_p N_Ip V_p fill at least this "
            "fraction of the node's dx^d (1: touching, for any shape function)")
        .greaterThan(0)
        .optional()
        .flag("surfaceGap",
              "surface-gap check: contact only where the bodies' surfaces, located from their nodal centres "
              "of mass through the shape function's half-space profile, touch or overlap")
        .orDefault(false)
        .word("normal", {"averaged", "largerGradient"},
              "the pair normal: averaged, (n_a - n_b) / |n_a - n_b| (Bardenhagen et al. 2001), or "
              "largerGradient, the normal of the body whose mass gradient at the node is the larger (Nairn's "
              "maximum volume "
              "gradient)")
        .orDefault("averaged")
        .dictionary("pairs", "per-pair laws: name { bodies (a b); friction mu; }")
        .optional();
}

}  // namespace

template <int Dim>
KeywordSchema MultiFieldContact<Dim>::keywords() {
    return KeywordSchema(Contact<Dim>::familyName, "multiField")
        .dictionary("multiFieldCoeffs", "the contact law (friction, separation, pairs)")
        .optional()
        .nested(&coeffKeywords);
}

template <int Dim>
MultiFieldContact<Dim>::MultiFieldContact(const Dictionary& dict) {
    const KeywordValues values = keywords().read(dict);
    if (!values.given("multiFieldCoeffs")) return;
    const KeywordValues& c = values.nested("multiFieldCoeffs");
    friction_ = c.scalar("friction");
    if (auto s = c.optionalScalar("separation")) separation_ = *s;
    largerGradient_ = c.word("normal") == "largerGradient";
    if (auto f = c.optionalScalar("volumeFraction")) volumeFraction_ = *f;
    surfaceGap_ = c.flag("surfaceGap");
    if (!c.given("pairs")) return;
    const Dictionary& pairs = c.dictionary("pairs");
    for (const auto& e : pairs.entries()) {
        if (!e->isDict())
            throw pairs.error(
                e->key, "a pair is a sub-dictionary: " + e->key + " { bodies (lower upper); friction 0.1; }");
        Pair p;
        p.dict = e->dict.get();
        const KeywordValues pv = pairKeywords().read(*p.dict);
        p.bodies = pv.words("bodies");
        if (p.bodies.size() != 2)
            throw pv.error("bodies", "a pair names two bodies, found " + std::to_string(p.bodies.size()));
        p.friction = pv.scalar("friction");
        pairs_.push_back(std::move(p));
    }
}

template <int Dim>
void MultiFieldContact<Dim>::bind(const std::vector<std::string>& bodies) {
    bodies_ = bodies.size();
    mu_.assign(bodies_ * bodies_, friction_);
    std::string valid;
    for (const auto& b : bodies) valid += (valid.empty() ? "" : " ") + b;
    std::vector<bool> set(bodies_ * bodies_, false);
    for (const auto& p : pairs_) {
        std::size_t id[2];
        for (int k = 0; k < 2; ++k) {
            const auto it = std::find(bodies.begin(), bodies.end(), p.bodies[k]);
            if (it == bodies.end())
                throw p.dict->error("bodies", "unknown body '" + p.bodies[k] +
                                                  "'; the bodies (particleGen "
                                                  "regions) of this run are: " +
                                                  valid);
            id[k] = std::size_t(it - bodies.begin());
        }
        if (id[0] == id[1])
            throw p.dict->error("bodies", "a contact law between body '" + p.bodies[0] +
                                              "' and itself: a pair names two different bodies of: " + valid);
        if (set[id[0] * bodies_ + id[1]])
            throw p.dict->error("bodies", "a second law for the pair (" + p.bodies[0] + " " + p.bodies[1] +
                                              "): each pair is given once");
        set[id[0] * bodies_ + id[1]] = set[id[1] * bodies_ + id[0]] = true;
        mu_[id[0] * bodies_ + id[1]] = mu_[id[1] * bodies_ + id[0]] = p.friction;
    }
}

template <int Dim>
std::vector<Vector<Dim>> MultiFieldContact<Dim>::correct(ContactNodes<Dim>& s, double dt) const {
    std::vector<Vector<Dim>> force(pairs(), Vector<Dim>::Zero());
    const std::size_t B = s.mass->size();
    if (B != bodies_)
        throw std::logic_error("contact multiField: correct() on " + std::to_string(B) +
                               " bodies, bound to " + std::to_string(bodies_));
    if (B < 2) return force;
    const std::size_t n = (*s.mass)[0].size();
    const auto& m = *s.mass;
    // The nodes where two or more bodies have mass: a parallel flag pass, then the few of them
    // (the interfaces) in node order, serially, so the pair sums are deterministic.
    shared_.resize(n);
    parallelFor(n, [&](std::size_t I) {
        int count = 0;
        for (std::size_t b = 0; b < B; ++b) count += m[b][I] >= s.massCutoff;
        shared_[I] = count >= 2;
    });
    auto& v = *s.velocity;
    const bool forces = s.acceleration != nullptr && dt > 0;
    const double reach = separation_ * s.cellSize;
    if (surfaceGap_) {
        if (!s.grid || !s.shape || !s.massPosition)
            throw std::logic_error(
                "contact multiField: surfaceGap needs the grid, shape function and centres");
        if (!profile_) profile_.emplace(*s.shape);
    }
    for (std::size_t I = 0; I < n; ++I) {
        if (!shared_[I]) continue;
        double M = 0;
        Vector<Dim> P = Vector<Dim>::Zero();
        for (std::size_t b = 0; b < B; ++b)
            if (m[b][I] >= s.massCutoff) M += m[b][I], P += m[b][I] * v[b][I];
        const Vector<Dim> vcm = P / M;
        for (std::size_t a = 0; a < B; ++a) {
            if (!(m[a][I] >= s.massCutoff)) continue;
            std::size_t o = B;
            for (std::size_t b = 0; b < B; ++b)
                if (b != a && m[b][I] >= s.massCutoff && (o == B || m[b][I] > m[o][I])) o = b;
            const Vector<Dim>& ga = (*s.massGradient)[a][I];
            const Vector<Dim>& go = (*s.massGradient)[o][I];
            const double la = ga.norm(), lo = go.norm();
            if (!(la > 0) || !(lo > 0)) continue;
            Vector<Dim> nrm;
            if (largerGradient_) {
                // The same body's normal for a and o (the larger |g|, ties to the lower index),
                // so n_oa = -n_ao and the pair's corrections stay equal and opposite.
                const bool own = la > lo || (la == lo && a < o);
                nrm = own ? Vector<Dim>(ga / la) : Vector<Dim>(-go / lo);
            } else {
                const Vector<Dim> d = ga / la - go / lo;  // n_a - n_o with n = g / |g|
                const double ld = d.norm();
                if (!(ld > 1e-12)) continue;  // parallel normals: no interface direction
                nrm = d / ld;
            }
            if (volumeFraction_ > 0 && s.volume &&
                (*s.volume)[a][I] + (*s.volume)[o][I] < volumeFraction_ * s.cellVolume)
                continue;
            if (s.massPosition && std::isfinite(reach)) {
                const Vector<Dim> xa = (*s.massPosition)[a][I] / m[a][I];
                const Vector<Dim> xo = (*s.massPosition)[o][I] / m[o][I];
                if ((xo - xa).dot(nrm) >= reach) continue;
            }
            if (surfaceGap_) {
                const Vector<Dim> xI = s.grid->nodePosition(typename CartesianGrid<Dim>::Index(I));
                const double hn = nrm.cwiseProduct(s.grid->cellSize()).norm();
                const double ca = ((*s.massPosition)[a][I] / m[a][I] - xI).dot(nrm) / hn;
                const double co = ((*s.massPosition)[o][I] / m[o][I] - xI).dot(nrm) / hn;
                if (-profile_->surface(-co) - profile_->surface(ca) > 0) continue;  // a gap between them
            }
            const Vector<Dim> w = v[a][I] - vcm;
            const double dn = w.dot(nrm);
            if (!(dn > 0)) continue;
            Vector<Dim> dv = -dn * nrm;
            const double mu = mu_[a * bodies_ + o];
            if (mu > 0) {
                const Vector<Dim> wt = w - dn * nrm;
                const double lt = wt.norm();
                if (lt > 0) dv -= (std::min(mu * dn, lt) / lt) * wt;
            }
            v[a][I] += dv;
            if (forces) {
                (*s.acceleration)[a][I] += dv / dt;
                // Counted once, on the pair's first body: its partner's correction is the reaction.
                if (a < o && (!s.countedNodes || (*s.countedNodes)[I]))
                    force[Contact<Dim>::pairIndex(a, o, B)] += (m[a][I] / dt) * dv;
            }
        }
    }
    return force;
}

template <int Dim>
std::string MultiFieldContact<Dim>::describe() const {
    std::ostringstream t;
    t << "multiField (friction " << friction_;
    if (std::isfinite(separation_)) t << ", separation " << separation_ << " cells";
    if (largerGradient_) t << ", normal largerGradient";
    if (volumeFraction_ > 0) t << ", volumeFraction " << volumeFraction_;
    if (surfaceGap_) t << ", surfaceGap";
    for (const auto& p : pairs_) t << ", " << p.bodies[0] << "-" << p.bodies[1] << " friction " << p.friction;
    t << ")";
    return t.str();
}

MFDYN_REGISTER_DIM(Contact, MultiFieldContact, "multiField",
                   "a node field per body, non-penetration and Coulomb friction (Bardenhagen et al. 2001)");

}  // namespace mfdyn
