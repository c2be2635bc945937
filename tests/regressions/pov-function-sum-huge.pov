#declare F = function(n) { sum(i, 1, n, i) };
#declare A = F(1e12);
