/* law_body.h: the body of the contact law (dm_law() and its output,
 * law.h), included twice by law.h: with DM_REAL double, as dm_law(), and
 * with DM_REAL float, as dm_lawf(), the law of the single-precision kernels
 * (DEMILL_WORLD_SINGLE_PRECISION; docs/design.md, Contact kernels), so that
 * the physics is written once. The includer defines DM_REAL, DM_LAW_NAME,
 * DM_LAW_OUT, DM_LAW_LOADS, DM_SQRT and DM_FABS, which the end of this file
 * undefines again for the next inclusion; DM_R(x) makes a constant or a pair
 * parameter a DM_REAL, so that the float law computes in float throughout
 * (in double it changes nothing). The laws beyond the fast kernels'
 * (elasto-plastic, cohesion) take their arguments in double, as they are
 * defined, whatever DM_REAL is: only the double law runs them. No include
 * guard: it is meant to be included more than once. */

#define DM_R(x) ((DM_REAL)(x))

typedef struct DM_LAW_OUT {
    DM_REAL fn;    /* normal force on b along n */
    DM_REAL fel;   /* its elastic part */
    DM_REAL ft[3]; /* tangential force on b (D components) */
    DM_REAL mr[3]; /* rolling torque on a (W components) */
    /* energy dissipated over the step, by mechanism (see dm_tally) */
    DM_REAL diss_normal, diss_tangential, diss_friction, diss_rolling;
    /* the extended laws' (dm_tally) */
    DM_REAL diss_plastic, diss_rolling_viscous, work_cohesion;
} DM_LAW_OUT;

DM_INLINE void DM_LAW_NAME(const int D, const int NL, const int DL, const int TL, const int RL,
                      const int CL, const dm_pairparam *pp, const DM_REAL *n, DM_REAL delta,
                      const DM_REAL *vc, const DM_REAL *dc, const DM_REAL *wrel, const DM_REAL *wd,
                      DM_REAL ir, DM_REAL rstar, DM_REAL mstar, DM_REAL dt_hist, DM_REAL reach,
                      int first, const DM_REAL *hin, DM_REAL *hout, DM_LAW_OUT *o)
{
    const int W = D == 3 ? 3 : 1;
    const int advance = dt_hist > DM_R(0.0);
    /* cohesion (docs/physics.md, Cohesion): a contact that exists may be
     * apart, δ < 0; the solids' laws see the overlap δ⁺ = max(δ, 0), and a
     * liquid bridge across a gap touches nothing solid */
    const DM_REAL dsol = CL != DEMILL_COHESION_NONE && delta < DM_R(0.0) ? DM_R(0.0) : delta;
    const int solid = CL != DEMILL_COHESION_CAPILLARY || delta > DM_R(0.0);

    /* normal law (§2): elastic force and contact stiffness S = dF/dδ */
    DM_REAL fel, stiff, sq = DM_R(0.0), plastic = DM_R(0.0);
    if (NL == DEMILL_NORMAL_LINEAR) {
        fel = DM_R(pp->kn) * dsol;
        stiff = DM_R(pp->kn);
    } else if (dm_normal_plastic(NL)) {
        /* the elasto-plastic laws (contact/plastic.h): the force on the
         * current branch, its unloading slope for S, the step's plastic
         * work; the history δ_max (and the multi-path law's onset). They
         * branch on the contact's state: only the generic kernel runs them */
        const int HN = dm_law_off_normal(NL, DL, TL, D);
        dm_plastic_out po;
        double hn[2] = {0.0, 0.0}; /* in double, whatever DM_REAL is */
        for (int c = 0; c < dm_plastic_hist_size(NL); c++)
            hn[c] = hin[HN + c];
        dm_plastic_law(NL, pp, rstar, dsol, hn, &po);
        fel = po.f;
        stiff = po.stiff;
        sq = DM_SQRT(rstar * dsol);
        plastic = advance ? po.diss : DM_R(0.0);
        hout[HN] = advance ? po.dmax : hin[HN];
        if (NL == DEMILL_NORMAL_PLASTIC_PATHS)
            hout[HN + 1] = advance ? po.onset : hin[HN + 1];
    } else {
        sq = DM_SQRT(rstar * dsol);
        fel = (DM_R(4.0) / DM_R(3.0)) * DM_R(pp->e_star) * sq * dsol;
        stiff = DM_R(2.0) * DM_R(pp->e_star) * sq;
    }
    /* the cohesive force: JKR's force of the contact radius a(δ) less the
     * Hertz force of δ⁺ (whose energy is stored as Hertz's), the contact's
     * stiffness then 2E* a and Mindlin's √(R* δ) its radius a (Thornton and
     * Yin 1991); or the bridge's attraction at the gap */
    DM_REAL fcoh = DM_R(0.0);
    if (CL == DEMILL_COHESION_JKR) {
        const DM_REAL a = dm_jkr_radius(delta, rstar, pp->e_star, pp->adhesion);
        double fh, fad;
        dm_jkr_force(a, rstar, pp->e_star, pp->adhesion, &fh, &fad);
        fcoh = fh + fad - fel;
        sq = a;
        stiff = DM_R(2.0) * DM_R(pp->e_star) * a;
    }
    if (CL == DEMILL_COHESION_CAPILLARY)
        fcoh = dm_capillary_force(dsol - delta, rstar, pp->surface_tension, pp->contact_angle,
                                  pp->liquid_volume);
    DM_REAL vn = DM_R(0.0);
    for (int c = 0; c < D; c++)
        vn += vc[c] * n[c];

    /* normal damping (§3) */
    DM_REAL cn = DM_R(0.0), root_ms = DM_R(0.0);
    if (DL == DEMILL_DAMPING_VISCOUS)
        cn = DM_R(pp->cn);
    if (DL == DEMILL_DAMPING_RESTITUTION) {
        root_ms = DM_SQRT(mstar * stiff);
        cn = DM_R(pp->dcoef) * root_ms;
    }
    if (CL == DEMILL_COHESION_CAPILLARY)
        cn = solid ? cn : DM_R(0.0);
    const int HT = dm_law_tangential_size(TL, D); /* exit slots: last force, overlap */
    DM_REAL vnd = vn; /* the normal velocity the dashpot sees */
    if (dm_law_exit(NL, DL)) {
        /* unclamped, in a continuing contact: the contact's own force
         * change over the step, implicitly: v = v_pred + h (F_new -
         * F_last)/m*, F_new = k δ - c v, with h the part of the step the
         * integrator's second kick covers */
        const DM_REAL hm = (DM_R(1.0) - reach) * dt_hist / mstar;
        const DM_REAL implicit = (vn + hm * (fel - hin[HT])) / (DM_R(1.0) + hm * cn);
        vnd = (!pp->clamp & (hin[HT + 1] > DM_R(0.0))) ? implicit : vn;
    }
    DM_REAL fn = fel - cn * vnd;
    fn = (pp->clamp & (fn < DM_R(0.0))) ? DM_R(0.0) : fn;
    const DM_REAL fn_now = fn;
    if (dm_law_entry(DL)) {
        /* first sample of an approaching contact: its age from the overlap
         * under the current deceleration, at most a step, then the
         * onset-exponent weight (see above): the impulse from contact to
         * the end of the sample's window, ∫ (t/age)^p dt over
         * [0, age + reach Δt], divided by Δt */
        const DM_REAL va = -vn, dec = fn / mstar;
        /* δ = va age + dec age²/2 (va the speed at the sample, after the
         * deceleration), solved for the root that is stable for dec -> 0 */
        const DM_REAL est = DM_R(2.0) * delta / (va + DM_SQRT(va * va + DM_R(2.0) * dec * delta));
        const DM_REAL a = (est < dt_hist ? est : dt_hist) / dt_hist, e = a + reach; /* steps */
        const int lin = NL == DEMILL_NORMAL_LINEAR || NL == DEMILL_NORMAL_WALTON_BRAUN;
        const DM_REAL w_d = lin ? e : DM_R(0.8) * e * DM_SQRT(DM_SQRT(e / a));
        const int young = advance & first & (va > DM_R(0.0));
        fn = young ? fel + w_d * (fn - fel) : fn;
    }
    if (dm_law_exit(NL, DL)) {
        hout[HT] = advance ? fn_now : hin[HT];
        hout[HT + 1] = advance ? dsol : hin[HT + 1];
    }
    /* the cohesive force joins after the clamp, which keeps the dashpot from
     * pulling but not the cohesion; the work done against it is booked
     * apart. Friction and rolling resistance are capped by the solids'
     * load: the contact force, or for JKR its sum with twice the pull-off
     * force (Thornton and Yin 1991), positive while the neck holds. */
    const DM_REAL load = CL == DEMILL_COHESION_JKR
                             ? fn + fcoh + DM_R(2.0) * dm_jkr_pull_off(rstar, pp->adhesion)
                             : fn;
    o->fn = CL != DEMILL_COHESION_NONE ? fn + fcoh : fn;
    o->fel = fel;
    o->diss_normal = -(fn - fel) * vnd * dt_hist;
    o->diss_tangential = o->diss_friction = o->diss_rolling = DM_R(0.0);
    o->diss_plastic = plastic;
    o->diss_rolling_viscous = DM_R(0.0);
    o->work_cohesion = -fcoh * vn * dt_hist;

    /* tangential law (§4) */
    DM_REAL vt[3], dt_rate[3], dn = DM_R(0.0);
    for (int c = 0; c < D; c++) {
        vt[c] = vc[c] - vn * n[c];
        dn += dc[c] * n[c];
        o->ft[c] = DM_R(0.0);
    }
    for (int c = 0; c < D; c++)
        dt_rate[c] = dc[c] - dn * n[c];
    const DM_REAL cap = DM_R(pp->mu) * DM_FABS(load);
    if (TL == DEMILL_TANGENTIAL_COULOMB) {
        DM_REAL vt2 = DM_R(0.0);
        for (int c = 0; c < D; c++)
            vt2 += vt[c] * vt[c];
        if (DL != DEMILL_DAMPING_RESTITUTION)
            root_ms = DM_SQRT(mstar * stiff);
        const DM_REAL vtm = DM_SQRT(vt2), fr = DM_R(pp->coul_reg) * root_ms * vtm;
        const int slip = fr > cap;
        const DM_REAL fm = slip ? cap : fr, scale = vt2 > DM_R(0.0) ? fm / vtm : DM_R(0.0);
        for (int c = 0; c < D; c++)
            o->ft[c] = -scale * vt[c];
        const DM_REAL lost = fm * vtm * dt_hist;
        o->diss_friction = slip ? lost : DM_R(0.0);
        o->diss_tangential = slip ? DM_R(0.0) : lost;
    }
    if (TL == DEMILL_TANGENTIAL_SPRING || TL == DEMILL_TANGENTIAL_MINDLIN) {
        DM_REAL kt;
        if (TL == DEMILL_TANGENTIAL_SPRING) {
            kt = DM_R(pp->kt);
        } else {
            if (NL == DEMILL_NORMAL_LINEAR)
                sq = DM_SQRT(rstar * delta);
            kt = DM_R(pp->g8) * sq;
        }
        DM_REAL ct = DM_R(0.0);
        if (DL == DEMILL_DAMPING_VISCOUS)
            ct = DM_R(pp->ct_factor) * DM_R(pp->cn);
        if (DL == DEMILL_DAMPING_RESTITUTION)
            ct = DM_R(pp->ct_factor) * DM_R(pp->dcoef) * DM_SQRT(mstar * kt);
        /* spring displacement: accumulate the step's relative displacement,
         * rotated into the tangent plane by removing its normal part (as
         * LIGGGHTS does; in 2D it is a scalar along t = (-n_y, n_x), which
         * turns with the contact by construction). The spring and dashpot
         * force together is capped at μ|F_n|; on slip the spring is reset to
         * carry the capped force. Dissipation is the work the contact absorbs
         * (the force times the velocity at the sample, over the step: the
         * impulse window in which the integrator applies it) less the change
         * of spring energy, so that the spring itself books no loss. */
        const int NS = D == 3 ? 3 : 1;
        DM_REAL xi[3], ds[3], ftr[3], vtl[3], e_old = DM_R(0.0);
        if (D == 3) {
            for (int c = 0; c < 3; c++) {
                ds[c] = dt_rate[c] * dt_hist;
                vtl[c] = vt[c];
            }
        } else {
            const DM_REAL tx = -n[1], ty = n[0];
            ds[0] = (dt_rate[0] * tx + dt_rate[1] * ty) * dt_hist;
            vtl[0] = vt[0] * tx + vt[1] * ty;
        }
        DM_REAL xn = DM_R(0.0);
        for (int c = 0; c < NS; c++) {
            e_old += hin[c] * hin[c];
            xi[c] = hin[c] + ds[c];
            if (D == 3)
                xn += xi[c] * n[c];
        }
        DM_REAL f2 = DM_R(0.0);
        for (int c = 0; c < NS; c++) {
            if (D == 3)
                xi[c] -= xn * n[c];
            ftr[c] = -kt * xi[c] - ct * vtl[c];
            f2 += ftr[c] * ftr[c];
        }
        const int slip = f2 > cap * cap;
        const DM_REAL scale = slip ? cap / DM_SQRT(f2) : DM_R(1.0), ikt = DM_R(1.0) / kt;
        DM_REAL work = DM_R(0.0), e_new = DM_R(0.0);
        for (int c = 0; c < NS; c++) {
            ftr[c] *= scale;
            xi[c] = slip ? -ftr[c] * ikt : xi[c];
            if (CL == DEMILL_COHESION_CAPILLARY) /* across a gap the spring lets go */
                xi[c] = solid ? xi[c] : DM_R(0.0);
            work -= ftr[c] * vtl[c] * dt_hist;
            e_new += xi[c] * xi[c];
            hout[c] = advance ? xi[c] : hin[c];
        }
        /* spring energies before and after the step; Mindlin's previous one
         * was stored, with the previous k_t */
        e_new *= DM_R(0.5) * kt;
        e_old = TL == DEMILL_TANGENTIAL_MINDLIN ? hin[NS] : DM_R(0.5) * kt * e_old;
        if (TL == DEMILL_TANGENTIAL_MINDLIN)
            hout[NS] = advance ? e_new : hin[NS];
        const DM_REAL lost = work - (e_new - e_old);
        o->diss_friction = slip ? lost : DM_R(0.0);
        o->diss_tangential = slip ? DM_R(0.0) : lost;
        if (D == 3) {
            for (int c = 0; c < 3; c++)
                o->ft[c] = ftr[c];
        } else {
            o->ft[0] = -n[1] * ftr[0];
            o->ft[1] = n[0] * ftr[0];
        }
    }

    /* rolling resistance (§5): constant torque, regularised near ω_rel = 0 */
    for (int c = 0; c < W; c++)
        o->mr[c] = DM_R(0.0);
    if (RL == DEMILL_ROLLING_CONSTANT_TORQUE) {
        DM_REAL w2 = DM_R(0.0);
        for (int c = 0; c < W; c++)
            w2 += wrel[c] * wrel[c];
        const DM_REAL wm = DM_SQRT(w2);
        const DM_REAL mr = DM_R(pp->roll_reg) * rstar * rstar * DM_SQRT(mstar * stiff) * wm;
        const DM_REAL mcap = DM_R(pp->mu_r) * rstar * DM_FABS(load);
        const DM_REAL mm = mr > mcap ? mcap : mr, scale = w2 > DM_R(0.0) ? mm / wm : DM_R(0.0);
        for (int c = 0; c < W; c++)
            o->mr[c] = -scale * wrel[c];
        o->diss_rolling = mm * wm * dt_hist;
    }
    if (RL == DEMILL_ROLLING_SPRING) {
        /* the elastic-plastic spring-dashpot (type C of Ai et al. 2011): the
         * spring's torque on a, M_k, accumulates -k_r Δθ_r, Δθ_r the step's
         * relative rotation without its twist about n; the torque kept from
         * the last step is turned into the current tangent plane by removing
         * its normal part (as the tangential spring is). |M_k| is capped at
         * μ_r R* |F_n|; below the cap the dashpot adds -c_r ω_r, at the cap
         * (full mobilisation) it is off (Ai et al.'s f = 0). The spring's
         * loss, its work less the change of its energy |M_k|²/(2 k_r), is
         * rolling friction (it is the slip at the cap); the dashpot's is the
         * rolling viscous term. */
        const int HR = dm_law_off_rolling(NL, DL, TL, D);
        const DM_REAL kr =
            DM_R(pp->kr) > DM_R(0.0)
                ? DM_R(pp->kr)
                : DM_R(2.25) * stiff * DM_R(pp->mu_r) * DM_R(pp->mu_r) * rstar * rstar;
        const DM_REAL cr = DM_R(pp->eta_r) * DM_R(2.0) * DM_SQRT(ir * kr);
        const DM_REAL half_ikr = kr > DM_R(0.0) ? DM_R(0.5) / kr : DM_R(0.0);
        DM_REAL twist = DM_R(0.0), twist_p = DM_R(0.0), mn = DM_R(0.0), m2 = DM_R(0.0);
        DM_REAL mk[3], wt[3];
        if (D == 3)
            for (int c = 0; c < 3; c++) {
                twist += wd[c] * n[c];
                twist_p += wrel[c] * n[c];
                mn += hin[HR + c] * n[c];
            }
        for (int c = 0; c < W; c++) {
            const DM_REAL nc = D == 3 ? n[c] : DM_R(0.0);
            wt[c] = wrel[c] - twist_p * nc;
            mk[c] = hin[HR + c] - mn * nc - kr * (wd[c] - twist * nc) * dt_hist;
            m2 += mk[c] * mk[c];
        }
        const DM_REAL mcap = DM_R(pp->mu_r) * rstar * DM_FABS(fn);
        const int full = m2 > mcap * mcap;
        const DM_REAL scale = full ? mcap / DM_SQRT(m2) : DM_R(1.0), c_on = full ? DM_R(0.0) : cr;
        DM_REAL work_k = DM_R(0.0), work_d = DM_R(0.0), e_new = DM_R(0.0);
        for (int c = 0; c < W; c++) {
            mk[c] *= scale;
            const DM_REAL md = -c_on * wt[c];
            o->mr[c] = mk[c] + md;
            work_k -= mk[c] * wt[c] * dt_hist;
            work_d -= md * wt[c] * dt_hist;
            e_new += mk[c] * mk[c];
            hout[HR + c] = advance ? mk[c] : hin[HR + c];
        }
        e_new *= half_ikr;
        hout[HR + W] = advance ? e_new : hin[HR + W];
        o->diss_rolling = advance ? work_k - (e_new - hin[HR + W]) : DM_R(0.0);
        o->diss_rolling_viscous = work_d;
    }
}

/* A law's output o as the pair's loads: the force on b, fn n + f_t, and the
 * torques on a and b (W components), the rolling torque and the lever arms
 * ai, aj (of a and b) times n × f_t (2D: its z component). */
DM_INLINE void DM_LAW_LOADS(const int D, const DM_REAL *n, DM_REAL ai, DM_REAL aj,
                            const DM_LAW_OUT *o, DM_REAL *f, DM_REAL *ta, DM_REAL *tb)
{
    const int W = D == 3 ? 3 : 1;
    DM_REAL nf[3];
    if (D == 3) {
        nf[0] = n[1] * o->ft[2] - n[2] * o->ft[1];
        nf[1] = n[2] * o->ft[0] - n[0] * o->ft[2];
        nf[2] = n[0] * o->ft[1] - n[1] * o->ft[0];
    } else {
        nf[0] = n[0] * o->ft[1] - n[1] * o->ft[0];
    }
    for (int c = 0; c < D; c++)
        f[c] = o->fn * n[c] + o->ft[c];
    for (int c = 0; c < W; c++) {
        ta[c] = o->mr[c] - ai * nf[c];
        tb[c] = -o->mr[c] - aj * nf[c];
    }
}

#undef DM_R
#undef DM_REAL
#undef DM_LAW_NAME
#undef DM_LAW_OUT
#undef DM_LAW_LOADS
#undef DM_SQRT
#undef DM_FABS
