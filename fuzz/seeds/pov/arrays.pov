// Arrays: sizes, initialisers, nesting, copies, dimension queries, arrays of items and strings.
#declare A = array[4] { 1, 2, 3, 4 };
#declare B = array[2][3] { { 1, 2, 3 }, { 4, 5, 6 } };
#declare C = array[3];
#declare C[0] = sphere { 0, 1 };
#declare C[1] = box { 0, 1 };
#declare C[2] = object { C[0] scale 2 };
#declare Words = array[2] { "text", "more" };
#declare D = A;
#declare D[0] = 10;
#declare N = dimensions(B) + dimension_size(B, 2);
#declare S = 0;
#for (I, 0, dimension_size(A, 1) - 1) #declare S = S + A[I]; #end
#ifdef (Words[1]) #debug Words[1] #end
#declare E = array[2] { array[2] { 1, 2 }, array[2] { 3, 4 } };
#declare M = array[2][2][2];
#declare M[1][1][1] = 8;
#declare Objs = array[3] { box { 0, 1 }, cylinder { 0, y, 1 }, cone { 0, 1, y, 0 } };
union { #for (I, 0, 2) object { Objs[I] translate I * x } #end pigment { rgb 1 } }
#declare R = array[2] { rand(seed(1)), rand(seed(2)) };
#macro Sum(Arr) #local T = 0; #for (I, 0, dimension_size(Arr, 1) - 1) #local T = T + Arr[I]; #end T #end
#declare Total = Sum(A);
