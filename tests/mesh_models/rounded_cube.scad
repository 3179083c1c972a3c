// A cube intersected with a sphere: flat faces meeting curved patches.
intersection() {
    cube(16, center = true);
    sphere(r = 10.5, $fn = 96);
}
