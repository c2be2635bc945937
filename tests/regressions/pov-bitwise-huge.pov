#declare A = bitwise_and(1e300, 3) + bitwise_or(pow(2, 40) + 3, 0);
#error concat("bitwise ", str(bitwise_and(1e300, 3), 0, 0), " ", str(bitwise_or(pow(2, 40) + 3, 0), 0, 0), " ", str(bitwise_xor(-1e300, 0), 0, 0))
