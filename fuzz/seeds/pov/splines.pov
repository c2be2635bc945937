// Splines of every kind, evaluated, copied and used in functions.
#declare L = spline { linear_spline -1, <0, 0, 0>, 0, <1, 1, 0>, 1, <2, 0, 1> };
#declare Q = spline { quadratic_spline 0, <0, 0, 0>, 1, <1, 2, 0>, 2, <2, 0, 1>, 3, <3, 1, 1> };
#declare C = spline { cubic_spline 0, <0, 0, 0>, 1, <1, 2, 0>, 2, <2, 0, 1>, 3, <3, 1, 1> };
#declare N = spline { natural_spline 0, 0, 1, 1, 2, 4, 3, 9 };
#declare Copy = spline { L };
#declare Sum = L(0.5) + Q(1.5) + C(2.5) + N(1.7) + Copy(-2);
#declare F = function { spline { linear_spline 0, <0, 0, 0>, 1, <1, 2, 3> } };
#declare G = F(0.25).y + F(0.75).z;
#for (T, 0, 3, 0.5) sphere { C(T), 0.1 } #end
sphere_sweep { cubic_spline 4, <0, 0, 0>, 0.1, <1, 1, 0>, 0.2, <2, 0, 0>, 0.1, <3, 1, 0>, 0.1 tolerance 0.01 }
sphere_sweep { linear_spline 2, 0, 0.5, x, 0.25 }
sphere_sweep { b_spline 4, 0, 0.1, y, 0.1, x, 0.1, z, 0.1 }
