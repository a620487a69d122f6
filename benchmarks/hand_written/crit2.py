"""Hand-written mutants of the criticism's naming, slips, verdict, run-order, one-run, discrimination, reach and edges
modules: plausible developer bugs that change a number or a decision a user reads.

Written by reading the modules, before any test was written against them.  First run (the held-out score, on the
tests of mutation.TABLE's rows, none aimed at these mutants): 16 of 16 killed (100.0 %), no survivors.
Re-run after the tests for the generated draws (seeds 42 and 43) were added: 16 of 16 killed.
"""
from hand_mutants import HandMutant

R = "demid/criticism/reach.py"
E = "demid/criticism/edges.py"
V = "demid/criticism/verdict.py"
N = "demid/criticism/naming.py"
S = "demid/criticism/slips.py"
O = "demid/criticism/run_order.py"
U = "demid/criticism/one_run.py"
D = "demid/criticism/discrimination.py"

MUTANTS = [
    # reach: the slope per actual unit taken along the outward direction (its sign wrong on a lower bound)
    HandMutant(R, "slope=float(outward * g / width)", "slope=float(g / width)",
               reads_wrong="on a lower bound the slope's sign, and the advice says the observable 'moves away' "
                           "where it gains (or the reverse)"),
    # reach: widening decided by the straight line's extension instead of the surrogate's quadratic
    HandMutant(R, "widen=bool(quadratic <= min(WIDEN_LIMIT, room))", "widen=bool(straight <= min(WIDEN_LIMIT, room))",
               reads_wrong="widening advised where the curved surrogate never reaches the band (or refused where "
                           "it does within half a range)"),
    # edges: the admissible set's sides not filtered by the physical limits (only the best point's are)
    HandMutant(E, "best, aset = movable_sides(domain, best), movable_sides(domain, aset)",
               "best = movable_sides(domain, best)",
               reads_wrong="'Widen the range' advised beyond a physical limit where the admissible set touches it"),
    # edges: the hull tolerance applied inwards instead of outwards
    HandMutant(E, "b_ub = np.concatenate([u + tol, -(u - tol)])", "b_ub = np.concatenate([u - tol, -(u + tol)])",
               reads_wrong="a reference point inside the runs' hull said to be outside it (extrapolated)"),
    # verdict: the leave-one-out RMSE divided by the residual degrees of freedom instead of the runs
    HandMutant(V, "loo = math.sqrt(st.press / n) if", "loo = math.sqrt(st.press / (n - st.n_params)) if",
               reads_wrong="the leave-one-out error quoted in 'does not predict' and loo_rmse too large"),
    # verdict: the replicated runs of an unexplained misfit chosen by signed, not absolute, studentised residual
    HandMutant(V, 'frame.reindex(frame["student_resid"].abs().sort_values(ascending=False, kind="stable").index)',
               'frame.reindex(frame["student_resid"].sort_values(ascending=False, kind="stable").index)',
               reads_wrong="the replicates proposed at the runs most above the surface, not the runs that misfit "
                           "most (a run far below is never replicated)"),
    # naming: the Bonferroni price of a chosen place taken in log-likelihood units on the AICc scale (not doubled)
    HandMutant(N, "price = 2.0 * math.log(choices.get(h.cause, 1))", "price = math.log(choices.get(h.cause, 1))",
               reads_wrong="candidates' gains and AICc differences, and which causes are close, wrong"),
    # naming: misfit left after the named cause judged at the family level, not the stricter residual level
    HandMutant(N, "if h.p_family <= RESIDUAL_MISFIT_LEVEL * family_alpha]", "if h.p_family <= family_alpha]",
               reads_wrong="a named cause turned into 'unexplained' by a residual test at p 0.01-0.05"),
    # slips: the prior over slips spread over factors only, not over both directions
    HandMutant(S, "weight = np.array([_SLIP_PRIOR[abs(d.power)] / (2 * n_factors) for d in same_run])",
               "weight = np.array([_SLIP_PRIOR[abs(d.power)] / n_factors for d in same_run])",
               reads_wrong="the slip's Bayes factor doubled: slips named (and readings listed) on half the evidence"),
    # slips: the mean shift's range taken as the response's standard deviation
    HandMutant(S, "spread = float(np.ptp(m.z))", "spread = float(np.std(m.z))",
               reads_wrong="the slip's Bayes factor a few times too small"),
    # run order: a run column sorted by a response in descending order not recognised
    HandMutant(O, "if abs(rho) >= SORTED_CORRELATION and (best is None", "if rho >= SORTED_CORRELATION and (best is None",
               reads_wrong="drift tested on a table printed in descending order of a response"),
    # run order: the sentence quotes the size of the correlation without its sign
    HandMutant(O, "{name} {rho:+.2f}), so a trend", "{name} {abs(rho):.2f}), so a trend",
               reads_wrong="a table sorted in descending order reported with a positive rank correlation"),
    # one run: the deleted run reported by its position among the model's runs, not its row in the data
    HandMutant(U, "return Deletion(int(np.flatnonzero(model.keep)[pos]), float(math.exp(logp[pos])))",
               "return Deletion(pos, float(math.exp(logp[pos])))",
               reads_wrong="after a dropped run, the run a cause rests on named as the next one"),
    # one run: the likelihood ratio's F form with the deleted run counted
    HandMutant(U, "out[pos] = f_logp((df - 1) * np.expm1(lr / (n - 1)), df - 1)",
               "out[pos] = f_logp((df - 1) * np.expm1(lr / n), df - 1)",
               reads_wrong="the p without the run quoted for unequal scatter too large (a cause kept that rests on "
                           "one run, or set aside wrongly)"),
    # discrimination: the deciding runs' target without the AICc gap the favoured candidate already leads by
    HandMutant(D, "d = z + math.sqrt(z * z + AMBIGUOUS_AICC + max(gap, 0.0))", "d = z + math.sqrt(z * z + AMBIGUOUS_AICC)",
               reads_wrong="too few deciding runs proposed where one candidate already leads"),
    # discrimination: a rival fitted far better than the named cause dropped (the margin taken both ways)
    HandMutant(D, 'if e["aicc"] - anchor["aicc"] <= margin:', 'if abs(e["aicc"] - anchor["aicc"]) <= margin:',
               reads_wrong="a cause named although a rival of another kind fits far better (not ambiguous)"),
]
