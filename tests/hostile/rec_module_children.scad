module m() { m() children(); }
m() cube();
