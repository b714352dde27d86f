"""The plain "which law wins where" lines of docs/results.md (reproduce.py): per index the law
with the lowest value in each scenario, and where the proposed law beats the proportional one."""


def write_law_winners(results, law_names, w):
    """results[scenario][law] -> metrics; law_names: the compared laws and their labels; w: writes a line."""
    LAW_NAMES = law_names
    for key, label in (("ise", "ISE ∫‖e‖²dt"), ("iae", "IAE ∫‖e‖dt"), ("tec", "TEC")):
        wins = []
        for n in results:
            best = min(tuple(LAW_NAMES), key=lambda law: results[n][law][key])
            wins.append(f"{n}: {LAW_NAMES[best]}")
        w(f"- Lowest {label} (proposed, fixed ρ, proportional): " + "; ".join(wins) + ".")
    beats = [n for n in results if results[n]["paper"]["ise"] < results[n]["proportional"]["ise"]]
    loses = [n for n in results if n not in beats]
    frugal = [n for n in results if results[n]["paper"]["tec"] <= min(results[n][law]["tec"] for law in LAW_NAMES)]
    w("- Which law wins where, plainly: on the integral error ∫‖e‖²dt the proposed law beats the proportional baseline on "
      + (", ".join(beats) or "no scenario") + " and loses to it on " + (", ".join(loses) or "none")
      + "; it spends the least control energy (TEC) on " + (", ".join(frugal) or "no scenario")
      + ". Fixed ρ's error is low only with the envelope rule rescuing it (widenings above).")
