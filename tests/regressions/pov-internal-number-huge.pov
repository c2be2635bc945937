#declare F = function { internal(1e10) };
