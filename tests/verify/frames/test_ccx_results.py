#!/usr/bin/python3
"""Checks of ccx_results.py on small files written here in ccx's layout (run by `make
verify-frames` before the comparison): fixed-width .frd values that touch, the .dat tables,
the section forces turned into member resultants, and refusals of what is not as expected."""
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from ccx_results import ParseError, dat_table, frd_block, section_resultants  # noqa: E402

FRD = """    1PSTEP                         1           1           1
  100CL  101 1.000000000           2                     0    1           1
 -4  STRESS      6    1
 -5  SXX         1    4    1    1
 -5  SYY         1    4    2    2
 -5  SZZ         1    4    3    3
 -5  SXY         1    4    1    2
 -5  SYZ         1    4    2    3
 -5  SZX         1    4    3    1
 -1         1 4.99980E+02 9.99960E+02 3.07046E-09 9.78337E+01-9.65654E+02 4.83106E+02
 -1        12-1.00000E+00-2.00000E+00-3.00000E+00-4.00000E+00-5.00000E+00-6.00000E+00
 -3
"""

DAT = """
 displacements (vx,vy,vz) for set JOINTS and time  0.1000000E+01

         1  5.293956E-23  7.888609E-31  1.323489E-23
         2  7.305832E-03 -1.632166E-04  2.898403E-10

 forces (fx,fy,fz) for set SUPPORTS and time  0.1000000E+01

         1  6.627570E+03  5.383678E+04 -1.258759E-06
"""


class CcxResults(unittest.TestCase):
    def write(self, text, suffix):
        fh = tempfile.NamedTemporaryFile("w", suffix=suffix, delete=False)
        fh.write(text)
        fh.close()
        self.addCleanup(os.unlink, fh.name)
        return fh.name

    def test_frd_fixed_width(self):
        rows = frd_block(self.write(FRD, ".frd"), "STRESS", 6)
        self.assertEqual(sorted(rows), [1, 12])
        self.assertEqual(rows[1][3:5], (97.8337, -965.654))
        self.assertEqual(rows[12], (-1.0, -2.0, -3.0, -4.0, -5.0, -6.0))

    def test_frd_refusals(self):
        with self.assertRaises(ParseError):   # no such block
            frd_block(self.write(FRD, ".frd"), "DISP", 3)
        with self.assertRaises(ParseError):   # components in another order
            frd_block(self.write(FRD.replace("SYZ", "SQQ"), ".frd"), "STRESS", 6)
        with self.assertRaises(ParseError):   # a row that is not a ' -1' row
            frd_block(self.write(FRD.replace(" -1        12", " -2        12"), ".frd"),
                      "STRESS", 6)

    def test_dat_tables(self):
        path = self.write(DAT, ".dat")
        disp = dat_table(path, "displacements", "joints")
        self.assertEqual(disp[2], (7.305832e-03, -1.632166e-04, 2.898403e-10))
        self.assertEqual(list(dat_table(path, "forces", "SUPPORTS")), [1])
        with self.assertRaises(ParseError):
            dat_table(path, "forces", "JOINTS")
        with self.assertRaises(ParseError):
            dat_table(self.write(DAT.replace("  2.898403E-10", ""), ".dat"), "displacements",
                      "JOINTS")

    def test_section_resultants(self):
        # The cantilever of README.md: along x, 1-direction z, tip force (0, -1000, 500) and
        # torque 100; at the root ccx gave SXX 500, SYY 1000, SXY 100, SYZ -800, SZX 400.
        r = section_resultants((500, 1000, 0, 100, -800, 400))
        # beamrotor's axes for that bar: y = +Y, z = +Z; the far part pulls the root part
        # with the tip force and the moment of (0.8, 0, 0) x tip force plus the torque.
        self.assertEqual((r["Vy"], r["Vz"], r["T"], r["My"], r["Mz"]),
                         (-1000, 500, 100, -400, -800))


if __name__ == "__main__":
    unittest.main()
