# Functions named by tests/data/good/everything.gdpn.yaml.

def removed(self, token):
    pass


def progress(self):
    return self.progress
