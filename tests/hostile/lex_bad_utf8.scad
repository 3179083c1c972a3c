echo("ÿşÃ");
â‚ = 1;
cube();
