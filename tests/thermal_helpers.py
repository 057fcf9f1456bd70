"""Tables of supports shared by the heat-balance tests (calc, cli, io): two bearings with calc headers."""
from __future__ import annotations

import math

import pandas as pd
from scipy.optimize import brentq

THERMAL_COLUMNS = ["n_thr [1/min]", "n_per [1/min]", "T_op [degC]", "nu_op [mm^2/s]", "Q_S [W]", "Q_L [W]"]


def supports(**extra):
    table = pd.DataFrame({
        "id": ["a", "b"], "designation": ["6205", "NU206-E"], "d [mm]": [25, 30], "D [mm]": [52, 62],
        "B [mm]": [15, 16], "C0 [kN]": [7.8, 36], "lubrication": ["oil_bath", "oil_bath"],
        "n [rpm]": [3000, 1500], "Fr [kN]": [2, 5],
    })
    for key, value in extra.items():
        table[key] = value
    return table


def plot_table(tmp_path, **extra):
    path = tmp_path / "supports.csv"
    supports(**{"nu40 [mm^2/s]": [68, 68], "nu100 [mm^2/s]": [8.6, 8.6], "T_amb [degC]": [20, 20],
                "T_bearing [degC]": [70, 70]}, **extra).to_csv(path, index=False)
    return path


# --- an axially loaded NJ208-E whose f2 comes from a chart: its heat balance by hand -----------------------------

#: a test chart (not from any catalogue): two curves at Fa/A = 1 and 100, f2 falling 20-fold from 1e3 to 1e8
NJ208_CHART = ("curve,Fa_over_A,nu_n_dM,f2,source\n-,1,mm^3/(s*min),1,-\nA,1,1000,0.02,test\n"
               "A,1,100000000,0.001,test\nB,100,1000,0.04,test\nB,100,100000000,0.002,test\n")
#: the NJ208-E's row: oil bath at 1000 1/min, Fr = 6 kN, Fa = 2 kN, oil of nu40 = 68, nu100 = 8.6 mm^2/s
NJ208_ROW = {"designation": "NJ208-E", "d [mm]": 40, "D [mm]": 80, "B [mm]": 18, "C0 [N]": 53000, "n [1/min]": 1000,
             "Fr [N]": 6000, "Fa [N]": 2000, "lubrication": "oil_bath", "nu40 [mm^2/s]": 68, "nu100 [mm^2/s]": 8.6,
             "T_amb [degC]": 20, "T_bearing [degC]": 70}


def nj208_chart(tmp_path):
    """The path of :data:`NJ208_CHART` written into ``tmp_path``."""
    path = tmp_path / "f2.csv"
    path.write_text(NJ208_CHART)
    return path


def walther_by_hand(nu40, nu100):
    """nu(theta) through nu40 and nu100 (ASTM D341: log log (nu + 0.7) linear in log T), by hand."""
    y40, y100 = (math.log10(math.log10(v + 0.7)) for v in (nu40, nu100))
    slope = (y40 - y100) / (math.log10(373.15) - math.log10(313.15))
    return lambda theta: 10 ** 10 ** (y40 - slope * (math.log10(theta + 273.15) - math.log10(313.15))) - 0.7


def nj208_chart_m2(nu_n):
    """M2 [N*mm] of the NJ208-E at nu*n [mm^2/s * 1/min] with f2 off :data:`NJ208_CHART`: dM = 60 mm, kB = 15 (the
    Schaeffler catalogue, p. 70), A = kB*1e-3*dM^2.1, f2 by log-log interpolation of the two curves at Fa/A."""
    dM, Fa = 60.0, 2000.0
    w = math.log(Fa / (15e-3 * dM ** 2.1)) / math.log(100.0)
    return 0.02 * (nu_n * dM / 1e3) ** (math.log(0.05) / math.log(1e5)) * 2 ** w * Fa * dM


def nj208_roots(m2=nj208_chart_m2):
    """(n_per at T_bearing 70 degC, T_op at 1000 1/min) of the NJ208-E by hand, with M2 = ``m2(nu*n)``: in an oil
    bath f0 = 2 and M1 = f1*Fr*dM with f1 = 0.0003 (the Schaeffler catalogue, pp. 66-69); N_R = pi*n/30e3*M_R
    against the seat's k_q*A_r*(T - 20 K), k_q = q_r/50 K, q_r = 0.016 W/mm^2 (HR 1), A_r = pi*B*(D + d)."""
    nu, dM = walther_by_hand(68, 8.6), 60.0

    def friction_power(n, v):
        return math.pi * n / 30e3 * (2.0 * (v * n) ** (2 / 3) * dM ** 3 * 1e-7 + 0.0003 * 6000 * dM + m2(v * n))

    k_q_A_r = 0.016 / 50 * math.pi * 18 * (80 + 40)
    n_per = brentq(lambda n: friction_power(n, nu(70)) - k_q_A_r * 50, 1, 1e5, xtol=1e-12)
    T_op = brentq(lambda T: friction_power(1000, nu(T)) - k_q_A_r * (T - 20), 20, 150, xtol=1e-12)
    return n_per, T_op
