self.b2.detach(self.d0)
