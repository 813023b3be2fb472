self.b0.vel1 = 2.0
self.b2.attach(self.d0)
