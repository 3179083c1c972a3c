cube()

