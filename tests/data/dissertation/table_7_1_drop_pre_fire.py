self.b1.vel1 = -2.0
self.b2.vel1 = 2.0
