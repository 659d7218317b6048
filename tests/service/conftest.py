"""Session fixtures: one redis-server and one `shadergen serve` shared by the service tests,
both on 127.0.0.1 and stopped at the end."""
import httpx
import pytest

from service_testing import RedisServer, Server, stop


@pytest.fixture(scope="session")
def redis_server(tmp_path_factory):
    server = RedisServer(tmp_path_factory.mktemp("redis"))
    yield server
    stop(server.proc)


@pytest.fixture(scope="session")
def server(tmp_path_factory):
    srv = Server(tmp_path_factory.mktemp("serve"))
    yield srv
    srv.close()


@pytest.fixture
def client(server) -> httpx.Client:
    return server.client


