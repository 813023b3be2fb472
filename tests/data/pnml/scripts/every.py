# Written for tests/net/pnml_test.cpp (every_construct.gdpn.yaml).
def removed(self, token):
    pass


def progress(self):
    pass
