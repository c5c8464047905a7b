// The scan report's 3-D view (three.js r111): the mesh coloured by cluster or by its vertex
// colours, the MVS points and the kept cameras as frusta. Reads its data from the
// <script id="avc-data"> JSON the report generator wrote (typed arrays as little-endian base64).
// Reports what happened in body[data-rendered]: "webgl" after the first frame, "svg" when the
// static renders below stand in for it.
(function () {
  'use strict';
  var body = document.body;
  var status = document.getElementById('view-status');
  window.addEventListener('error', function (event) {
    body.setAttribute('data-js-error', String(event.message));
  });

  function fallBack(why) {
    body.classList.add('no-webgl');
    body.setAttribute('data-rendered', 'svg');
    status.textContent = why + ': the static renders below show the model.';
  }

  function decode(base64, Type) {
    var text = atob(base64);
    var bytes = new Uint8Array(text.length);
    for (var i = 0; i < text.length; ++i) bytes[i] = text.charCodeAt(i);
    return new Type(bytes.buffer);
  }

  // One vertex per face corner, so each face can carry its own cluster colour.
  function unindex(values, indices, width, scale) {
    var out = new Float32Array(indices.length * width);
    for (var i = 0; i < indices.length; ++i) {
      for (var k = 0; k < width; ++k) out[i * width + k] = values[indices[i] * width + k] * scale;
    }
    return out;
  }

  function faceColours(rgb, faces) {
    var out = new Float32Array(faces * 9);
    for (var f = 0; f < faces; ++f) {
      for (var corner = 0; corner < 3; ++corner) {
        for (var k = 0; k < 3; ++k) out[f * 9 + corner * 3 + k] = rgb[f * 3 + k] / 255;
      }
    }
    return out;
  }

  if (typeof THREE === 'undefined') return fallBack('three.js is missing');
  var data = JSON.parse(document.getElementById('avc-data').textContent);
  var box = document.getElementById('view3d');
  var renderer;
  try {
    renderer = new THREE.WebGLRenderer({antialias: true, preserveDrawingBuffer: true});
  } catch (error) {
    return fallBack('WebGL is not available (' + error.message + ')');
  }
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setClearColor(0xf4f6f8);
  box.appendChild(renderer.domElement);

  var scene = new THREE.Scene();
  var centre = new THREE.Vector3().fromArray(data.centre);
  var radius = data.radius;
  var camera = new THREE.PerspectiveCamera(40, 1, radius / 100, radius * 200);
  camera.up.set(0, 0, 1);  // the cell's world has z up
  camera.position.copy(centre).add(new THREE.Vector3(2.0, -3.0, 1.8).multiplyScalar(radius));
  camera.lookAt(centre);
  scene.add(new THREE.AmbientLight(0xffffff, 0.55));
  var headlight = new THREE.DirectionalLight(0xffffff, 0.6);
  headlight.position.set(0.3, 0.5, 1);
  camera.add(headlight);
  scene.add(camera);

  var mesh = data.mesh;
  var indices = decode(mesh.indices, Int32Array);
  var faces = indices.length / 3;
  var geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position',
                        new THREE.BufferAttribute(unindex(decode(mesh.positions, Float32Array),
                                                          indices, 3, 1), 3));
  geometry.computeVertexNormals();
  var byCluster = faceColours(decode(mesh.face_rgb, Uint8Array), faces);
  var byVertex = mesh.vertex_rgb ? unindex(decode(mesh.vertex_rgb, Uint8Array), indices, 3, 1 / 255)
                                 : null;
  var colours = new THREE.BufferAttribute(byCluster.slice(), 3);
  geometry.setAttribute('color', colours);
  scene.add(new THREE.Mesh(geometry, new THREE.MeshLambertMaterial(
      {vertexColors: THREE.VertexColors, side: THREE.DoubleSide})));

  var points = null;
  if (data.points) {
    var cloud = new THREE.BufferGeometry();
    cloud.setAttribute('position',
                       new THREE.BufferAttribute(decode(data.points.positions, Float32Array), 3));
    var rgb = decode(data.points.rgb, Uint8Array);
    var pointColours = new Float32Array(rgb.length);
    for (var i = 0; i < rgb.length; ++i) pointColours[i] = rgb[i] / 255;
    cloud.setAttribute('color', new THREE.BufferAttribute(pointColours, 3));
    points = new THREE.Points(cloud, new THREE.PointsMaterial(
        {size: radius / 120, vertexColors: THREE.VertexColors}));
    points.visible = false;
    scene.add(points);
  }

  // Each camera: its centre and the four image corners at a small depth; 8 edges.
  var frusta = null;
  if (data.cameras.length) {
    var lines = [], lineColours = [];
    data.cameras.forEach(function (cam) {
      var p = cam.corners;  // 5 points: centre, then corners in order
      var colour = new THREE.Color(cam.colour);
      var edges = [[0, 1], [0, 2], [0, 3], [0, 4], [1, 2], [2, 3], [3, 4], [4, 1]];
      edges.forEach(function (edge) {
        edge.forEach(function (k) {
          lines.push(p[k * 3], p[k * 3 + 1], p[k * 3 + 2]);
          lineColours.push(colour.r, colour.g, colour.b);
        });
      });
    });
    var frustumGeometry = new THREE.BufferGeometry();
    frustumGeometry.setAttribute('position',
                                 new THREE.BufferAttribute(new Float32Array(lines), 3));
    frustumGeometry.setAttribute('color',
                                 new THREE.BufferAttribute(new Float32Array(lineColours), 3));
    frusta = new THREE.LineSegments(frustumGeometry,
                                    new THREE.LineBasicMaterial({vertexColors: THREE.VertexColors}));
    frusta.visible = false;
    scene.add(frusta);
  }

  function render() {
    renderer.render(scene, camera);
    if (body.getAttribute('data-rendered') !== 'webgl') {
      body.setAttribute('data-rendered', 'webgl');
      status.textContent = 'Drag to rotate, wheel to zoom' +
                           (typeof THREE.OrbitControls === 'function' ? ', right-drag to pan.' : '.');
    }
  }

  function resize() {
    var width = box.clientWidth, height = box.clientHeight;
    renderer.setSize(width, height);
    camera.aspect = width / height;
    camera.updateProjectionMatrix();
    render();
  }

  var controls = null;
  if (typeof THREE.OrbitControls === 'function') {
    controls = new THREE.OrbitControls(camera, renderer.domElement);
    controls.target.copy(centre);
    controls.update();
    controls.addEventListener('change', render);
  } else {
    orbit(camera, renderer.domElement, centre, render);
  }

  function toggle(id, apply) {
    var input = document.getElementById(id);
    if (!input) return;
    apply(input.checked);  // a reloaded page keeps its inputs' states
    input.addEventListener('change', function () {
      apply(input.checked);
      render();
    });
  }
  toggle('colour-by-vertex', function (on) {
    colours.array.set(on && byVertex ? byVertex : byCluster);
    colours.needsUpdate = true;
  });
  toggle('show-points', function (on) { if (points) points.visible = on; });
  // The cameras stand well away from the plant: showing them backs the view off until they fit.
  var cameraReach = 0;
  data.cameras.forEach(function (cam) {
    cameraReach = Math.max(cameraReach, centre.distanceTo(new THREE.Vector3().fromArray(cam.corners)));
  });
  toggle('show-cameras', function (on) {
    if (!frusta) return;
    frusta.visible = on;
    var offset = camera.position.clone().sub(centre);
    if (on && offset.length() < cameraReach * 2.4) {
      camera.position.copy(centre).add(offset.setLength(cameraReach * 2.4));
      if (controls) controls.update();
    }
  });
  window.addEventListener('resize', resize);
  resize();

  // A small orbit control for when three.js comes without OrbitControls: drag turns the view
  // about the target, the wheel moves nearer or farther.
  function orbit(cam, element, target, changed) {
    var offset = cam.position.clone().sub(target);
    var distance = offset.length();
    var azimuth = Math.atan2(offset.y, offset.x);
    var elevation = Math.asin(offset.z / distance);
    var last = null;
    function place() {
      cam.position.set(Math.cos(elevation) * Math.cos(azimuth), Math.cos(elevation) * Math.sin(azimuth),
                       Math.sin(elevation)).multiplyScalar(distance).add(target);
      cam.lookAt(target);
      changed();
    }
    element.addEventListener('pointerdown', function (e) { last = [e.clientX, e.clientY]; });
    window.addEventListener('pointerup', function () { last = null; });
    element.addEventListener('pointermove', function (e) {
      if (!last) return;
      azimuth -= (e.clientX - last[0]) * 0.01;
      elevation = Math.max(-1.5, Math.min(1.5, elevation + (e.clientY - last[1]) * 0.01));
      last = [e.clientX, e.clientY];
      place();
    });
    element.addEventListener('wheel', function (e) {
      e.preventDefault();
      distance *= e.deltaY > 0 ? 1.1 : 1 / 1.1;
      place();
    });
  }
})();
