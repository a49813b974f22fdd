#!/usr/bin/env python3
"""Chart of `gearstiff faults`: the mesh stiffness of the pass of the faulty tooth against the
healthy pass at the same mesh positions, and, for a root crack whose faces meet, its tip's
stress intensity factors.

    plot_faults.py FAULT_SWEEP.csv FAULT_TEXT [CRACK_TIP.csv] OUT.png

FAULT_TEXT is the report's "fault" line (which gear, which tooth, what fault). CSV headers are
"name [unit]" as written by the command; the PNG path is the last argument.
"""
import sys

from dynamics_charts import plt, read


def main(argv):
    sweep_path, fault, png = argv[1], argv[2], argv[-1]
    tip_path = argv[3] if len(argv) > 4 else None
    _, c = read(sweep_path)
    position = c["mesh_position [-]"]
    rows = 2 if tip_path else 1
    fig, axes = plt.subplots(rows, 1, figsize=(9, 4.2 * rows), sharex=True, squeeze=False)
    ax = axes[0][0]
    ax.plot(position, c["healthy_stiffness [N/um]"], "o-", ms=3, lw=1, label="healthy pass")
    touching = [i for i, lost in enumerate(c["lost_contact [-]"]) if lost == 0]
    ax.plot([position[i] for i in touching], [c["faulty_stiffness [N/um]"][i] for i in touching],
            "s-", ms=3, lw=1, color="C3", label="faulty pass")
    lost = [position[i] for i, v in enumerate(c["lost_contact [-]"]) if v != 0]
    if lost:
        ax.plot(lost, [0.0] * len(lost), "kx", label="no pair touches (no stiffness)")
    ax.set_ylabel("mesh stiffness k [N/µm]")
    ax.set_title("Mesh stiffness with the faulty tooth — " + fault, fontsize=9)
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=8)
    if tip_path:
        _, t = read(tip_path)
        ax2 = axes[1][0]
        ax2.plot(t["mesh_position [-]"], t["K_I [MPa*m^0.5]"], "o-", ms=3, lw=1, label="K_I")
        ax2.plot(t["mesh_position [-]"], t["K_II [MPa*m^0.5]"], "s--", ms=3, lw=1, label="K_II")
        ax2.set_ylabel("stress intensity at the crack tip [MPa·√m]")
        ax2.set_title("Crack tip stress intensity factors", fontsize=9)
        ax2.grid(True, lw=0.3)
        ax2.legend(fontsize=8)
    axes[-1][0].set_xlabel("mesh position [base pitches]")
    fig.tight_layout()
    fig.savefig(png, dpi=120)


if __name__ == "__main__":
    main(sys.argv)
