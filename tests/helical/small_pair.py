"""The small coarse helical pair of helical.sweep_dynamics as `--set` entries (z 19/29, m_n 2 mm,
β ±10°, b 8 mm, 20 N·m; 5 layers and the coarse sizes), shared by the tests that solve it."""
PAIR = ["Gear pair/Pinion/teeth=19", "Gear pair/Wheel/teeth=29",
        "Gear pair/Pinion/module=2", "Gear pair/Wheel/module=2",
        "Gear pair/Pinion/profile shift=0", "Gear pair/Wheel/profile shift=0",
        "Gear pair/Pinion/face width=8", "Gear pair/Wheel/face width=8",
        "Gear pair/Pinion/helix angle=10", "Gear pair/Wheel/helix angle=-10",
        "Gear pair scene/pinion torque=20"]
MESH = ["Mesh/dimension=3", "Mesh/layers=5", "Mesh/contact size=0.15", "Mesh/fine radius=0.4",
        "Mesh/body size=0.75", "Mesh/rim size=2.5"]
