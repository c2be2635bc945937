// Expressions: vectors, colours, dot members, built-in functions, identifiers of every type,
// trace/inside/min_extent on objects, clock and image size.
#declare V = <1, 2, 3> * 2 + <1, 1> - x;
#declare W = vnormalize(vcross(V, y)) + vrotate(x, <0, 90, 0>) + vaxis_rotate(x, y, 45);
#declare L = vlength(V) + vdot(V, W) + V.x + V.y + V.z + V.red + V.blue;
#declare C = rgbft <1, 0.5, 0, 0.1, 0.2> * 0.5;
#declare G = C.gray + C.filter + C.transmit + C.green;
#declare M = max(1, 2, 3) + min(1, 2) + atan2(1, 1) + asinh(1) + acosh(2) + atanh(0.5) + sinh(1) + cosh(1) + tanh(1);
#declare B = bitwise_and(12, 10) + bitwise_or(12, 10) + bitwise_xor(12, 10);
#declare R = seed(42); #declare X = rand(R) + rand(R);
#declare T = vturbulence(2, 0.5, 6, <1, 2, 3>);
#declare Obj = sphere { 0, 1 };
#declare Norm = <0, 0, 0>;
#declare Hit = trace(Obj, <0, 0, -5>, z, Norm);
#declare In = inside(Obj, <0, 0, 0>);
#declare Lo = min_extent(Obj); #declare Hi = max_extent(Obj);
#declare K = clock + clock_delta + frame_number + initial_frame + final_frame + initial_clock + final_clock + clock_on;
#declare I = image_width / image_height;
#declare Y = pi + (1 ? 2 : 3) + -(-(+1)) + 1e-3 + .5 + 5.;
#declare Z = <1, 2, 3, 4, 5>;
#declare Q = (1 < 2) + (1 = 1) + (1 != 2) + (V.x >= 2) + (V.z <= 6);
#declare Tex = texture { pigment { rgb V } };
#declare Fin = finish { ambient G };
#declare Nor = normal { bumps 0.1 };
#declare Int = interior { ior 1.3 };
#declare Pig = pigment { rgb 1 };
sphere { Hit, 0.1 texture { Tex finish { Fin } normal { Nor } } interior { Int } }
