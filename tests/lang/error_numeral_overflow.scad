// An overflowing numeral after a minus sign: a syntax error in 2021.01
echo(-1e400);
