<?xml version="1.0" encoding="UTF-8"?>
<tileset version="1.8" tiledversion="1.8.2" name="meadow" tilewidth="32" tileheight="32" tilecount="32" columns="8">
 <image source="meadow.png" width="256" height="128"/>
  <tile id="0">
   <properties>
    <property name="collider" type="bool" value="true"/>
   </properties>
  </tile>
  <tile id="1">
   <properties>
    <property name="collider" type="bool" value="true"/>
   </properties>
  </tile>
  <tile id="2">
   <properties>
    <property name="collider" type="bool" value="true"/>
   </properties>
  </tile>
  <tile id="3">
   <properties>
    <property name="collider" type="bool" value="true"/>
   </properties>
  </tile>
  <tile id="4">
   <properties>
    <property name="collider" type="bool" value="true"/>
   </properties>
  </tile>
  <tile id="5">
   <properties>
    <property name="collider" type="bool" value="true"/>
   </properties>
  </tile>
  <tile id="6">
   <properties>
    <property name="collider" type="bool" value="true"/>
   </properties>
  </tile>
  <tile id="7">
   <properties>
    <property name="collider" type="bool" value="true"/>
   </properties>
  </tile>
  <tile id="8">
   <properties>
    <property name="collider" type="bool" value="true"/>
   </properties>
  </tile>
  <tile id="9">
   <properties>
    <property name="collider" type="bool" value="true"/>
   </properties>
  </tile>
  <tile id="10">
   <properties>
    <property name="collider" type="bool" value="true"/>
   </properties>
  </tile>
  <tile id="16">
   <properties>
    <property name="collider" type="bool" value="true"/>
   </properties>
  </tile>
  <tile id="17">
   <properties>
    <property name="collider" type="bool" value="true"/>
   </properties>
  </tile>
  <tile id="24">
   <properties>
    <property name="collider" type="bool" value="true"/>
   </properties>
  </tile>
  <tile id="25">
   <properties>
    <property name="collider" type="bool" value="true"/>
   </properties>
  </tile>
  <tile id="26">
   <properties>
    <property name="collider" type="bool" value="true"/>
   </properties>
  </tile>
  <tile id="27">
   <properties>
    <property name="collider" type="bool" value="true"/>
   </properties>
  </tile>
</tileset>
