// User functions: parameters, sum/prod, internal(N), calls of earlier functions, select,
// functions in isosurfaces and patterns.
#declare F1 = function { x * x + y * y + z * z - 1 };
#declare F2 = function(a, b, c) { a * b + c };
#declare F3 = function(n) { sum(i, 1, n, i * i) + prod(j, 1, 4, j) };
#declare F4 = function { F1(x, y, z) * 0.5 + F2(x, y, z) };
#declare F5 = function { select(x, -1, 0, 1) + min(x, y, z) + max(x, 1) + abs(y) + sqrt(z * z) };
#declare F6 = function { internal(0) };
#declare F7 = function { internal(1) };
#declare F8 = function { internal(8) };
#declare F8b = function(a, b, c, d) { F8(a, b, c, 1, d) };
#declare F9 = function { sin(x) + cos(y) + tan(z) + exp(x) + ln(1 + x * x) + log(2) + pow(x, 2) + atan2(y, x) };
#declare F10 = function { floor(x) + ceil(y) + int(z) + mod(x, 2) + ceil(pi) + degrees(1) + radians(90) };
#declare F11 = function { pigment { checker color rgb 0 color rgb 1 } };
#declare F12 = function { pattern { bozo } };
#declare F13 = function { transform { rotate 45 * y } };
#declare V = F1(1, 2, 3) + F2(1, 2, 3) + F3(5) + F4(0, 0, 0) + F5(1, -2, 3) + F9(0.5, 0.5, 0.5);
#declare W = F11(0.5, 0, 0).red + F13(1, 0, 0).x;
isosurface {
  function { F1(x, y, z) + 0.1 * sin(8 * x) }
  contained_by { box { -2, 2 } }
  threshold 0 accuracy 0.001 max_gradient 5 evaluate 1, 10, 0.99
  pigment { rgb 1 }
}
parametric {
  function { sin(u) * cos(v) }, function { sin(u) * sin(v) }, function { cos(u) }
  <0, 0>, <2 * pi, pi>
  contained_by { sphere { 0, 1.1 } }
  precompute 10, x, y, z
}
plane { y, -1 pigment { function { abs(sin(x * 4)) } color_map { [0 rgb 0] [1 rgb 1] } } }
